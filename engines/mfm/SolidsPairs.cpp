#include "engines/mfm/SolidsPairs.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <utility>

namespace grainbridge::mfm {

SolidsPairsResult solidsPairsFor(const std::vector<SolidsPhase>& solids, const std::vector<SolidsPairRequest>& requests) {
  SolidsPairsResult out;
  const auto problem = [&](std::string pointer, std::string message) {
    out.problems.push_back({std::move(pointer), std::move(message)});
  };
  const std::size_t M = solids.size();
  std::map<std::string, std::size_t> phaseIndex;  // name -> 1-based phase
  for (std::size_t m = 0; m < M; ++m) {
    if (!phaseIndex.emplace(solids[m].name, m + 1).second)
      problem("/solids/" + std::to_string(m) + "/name", "\"" + solids[m].name + "\" names another phase too");
  }
  for (std::size_t l = 1; l <= M; ++l) {
    for (std::size_t m = l + 1; m <= M; ++m) {
      SolidsPair pair{l, m, {}};
      pair.drag.restitution = 0.5 * (solids[l - 1].restitution + solids[m - 1].restitution);
      out.pairs.push_back(pair);
    }
  }
  std::set<std::pair<std::size_t, std::size_t>> listed;
  for (std::size_t k = 0; k < requests.size(); ++k) {
    const SolidsPairRequest& request = requests[k];
    const std::string at = "/solids_pairs/" + std::to_string(k);
    if (request.phases.size() != 2) {
      problem(at + "/phases", "names " + std::to_string(request.phases.size()) + " phases; a pair is two");
      continue;
    }
    std::array<std::size_t, 2> index{0, 0};
    for (std::size_t i = 0; i < 2; ++i) {
      const auto found = phaseIndex.find(request.phases[i]);
      if (found == phaseIndex.end()) {
        problem(at + "/phases/" + std::to_string(i), "no solids phase is named \"" + request.phases[i] + "\"");
      } else {
        index[i] = found->second;
      }
    }
    if (index[0] == 0 || index[1] == 0) continue;
    if (index[0] == index[1]) {
      problem(at + "/phases", "names \"" + request.phases[0] + "\" twice; a pair is two phases");
      continue;
    }
    const auto key = std::minmax(index[0], index[1]);
    if (!listed.insert(key).second) {
      problem(at, "the pair " + request.phases[0] + ", " + request.phases[1] + " is listed before");
      continue;
    }
    for (SolidsPair& pair : out.pairs) {
      if (pair.l != key.first || pair.m != key.second) continue;
      pair.drag.frictionCoefficient = request.friction;
      if (request.restitution) pair.drag.restitution = *request.restitution;
    }
  }
  return out;
}

}  // namespace grainbridge::mfm
