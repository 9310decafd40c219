#include "workflows/report/Realisations.hpp"

#include <algorithm>
#include <numeric>

#include "workflows/report/SweepLabel.hpp"

namespace grainbridge::workflows::report {

using nlohmann::json;

std::vector<Arm> groupArms(const std::vector<SweptRun>& runs, const std::string& realisation) {
  // Per arm, its runs with their realisation values (null for a run not swept over it), gathered
  // first and ordered by value before they are written into the arm.
  struct Member {
    json value;
    std::size_t run;
  };
  std::vector<Arm> arms;
  std::vector<std::vector<Member>> members;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const SweptRun& run = runs[r];
    const bool realised = run.written.contains(realisation);
    json shared = run.written;
    if (realised) shared.erase(realisation);
    std::size_t a = 0;
    while (a < arms.size() && !(realised && !members[a].front().value.is_null() && arms[a].stage == run.stage &&
                                arms[a].written == shared))
      ++a;
    if (a == arms.size()) {
      arms.push_back({sweepLabel(run.stage, shared), run.stage, shared, {}, {}});
      members.emplace_back();
    }
    members[a].push_back({realised ? run.written.at(realisation) : json(), r});
  }
  for (std::size_t a = 0; a < arms.size(); ++a) {
    // By realisation value (seed 2 before seed 10), whatever order the runs came in.
    std::stable_sort(members[a].begin(), members[a].end(),
                     [](const Member& x, const Member& y) { return x.value < y.value; });
    for (const Member& m : members[a]) {
      arms[a].runs.push_back(m.run);
      if (!m.value.is_null()) arms[a].realisations.push_back(writtenText(m.value));
    }
  }
  std::stable_sort(arms.begin(), arms.end(), [](const Arm& a, const Arm& b) {
    return a.label != b.label ? a.label < b.label : a.stage < b.stage;
  });
  return arms;
}

RealisationStatistics overRealisations(const std::vector<double>& values) {
  RealisationStatistics s;
  s.n = values.size();
  if (values.empty() || !std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); })) {
    return s;
  }
  s.mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(s.n);
  if (s.n < 2) return s;
  double squares = 0.0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(squares / static_cast<double>(s.n - 1));
  s.se = s.sd / std::sqrt(static_cast<double>(s.n));
  return s;
}

MeanDifference meanDifference(const RealisationStatistics& from, const RealisationStatistics& to) {
  return {to.mean - from.mean, std::hypot(from.se, to.se)};
}

std::vector<ArmContrast> armContrasts(const std::vector<Arm>& arms) {
  std::vector<ArmContrast> contrasts;
  for (std::size_t a = 0; a < arms.size(); ++a) {
    for (std::size_t b = a + 1; b < arms.size(); ++b) {
      const Arm &from = arms[a], &to = arms[b];
      if (from.stage != to.stage || from.runs.size() < 2 || to.runs.size() < 2) continue;
      if (from.written.size() != to.written.size()) continue;
      std::vector<std::string> differing;
      bool sameParameters = true;
      for (const auto& [k, v] : from.written.items()) {
        if (!to.written.contains(k)) {
          sameParameters = false;
          break;
        }
        if (to.written.at(k) != v) differing.push_back(k);
      }
      if (sameParameters && differing.size() == 1) contrasts.push_back({a, b, differing.front()});
    }
  }
  return contrasts;
}

}  // namespace grainbridge::workflows::report
