#include "engines/mfm/Segregation.hpp"

#include <array>

#include "core/text/NumberText.hpp"
#include "engines/mfm/InitialBed.hpp"

namespace grainbridge::mfm {

namespace {

// Refused when `small` names the larger diameter; equal diameters make the roles a matter of
// naming only, warned.
void checkRoles(const SolidsPhase& small, const SolidsPhase& large, SegregationSetup& out) {
  if (small.diameter > large.diameter) {
    out.problems.push_back({"/segregation/small",
                            "names \"" + small.name + "\" (diameter " + core::humanNumber(small.diameter) +
                                " m), larger than large \"" + large.name + "\" (" + core::humanNumber(large.diameter) +
                                " m): s_p (Eqs. 5.23-5.25) would have the wrong sign; swap small and large"});
  } else if (small.diameter == large.diameter) {
    out.warnings.push_back({"/segregation", "small \"" + small.name + "\" and large \"" + large.name +
                                                "\" have the same diameter " + core::humanNumber(small.diameter) +
                                                " m: s_p (Eqs. 5.23-5.25) measures the separation of two equal "
                                                "grains, its sign set by the names alone"});
  }
}

}  // namespace

SegregationSetup segregationOf(const SegregationRoles& roles, const MultiFluidSetup& setup, const InitialState& initial,
                               bool measure) {
  SegregationSetup out;
  const auto& solids = setup.model.solids;
  const std::size_t M = solids.size();
  if (M != 2) {
    out.problems.push_back({"/segregation", "the segregation percentage is of a binary bed; this one has " +
                                                std::to_string(M) + " solids phase(s)"});
  }
  std::array<std::size_t, 2> index{M, M};
  const std::array<const std::string*, 2> names{&roles.small, &roles.large};
  const std::array<const char*, 2> keys{"small", "large"};
  for (std::size_t r = 0; r < 2; ++r) {
    for (std::size_t m = 0; m < M; ++m) {
      if (solids[m].name == *names[r]) index[r] = m;
    }
    if (index[r] == M)
      out.problems.push_back(
          {"/segregation/" + std::string(keys[r]), "no solids phase is named \"" + *names[r] + "\""});
  }
  if (index[0] < M && index[0] == index[1])
    out.problems.push_back({"/segregation/large", "is the small phase too; name the two phases of the bed"});
  if (index[0] < M && index[1] < M && index[0] != index[1]) checkRoles(solids[index[0]], solids[index[1]], out);
  if (!measure || !out.problems.empty()) return out;
  const auto volumes = initialInventory(setup, initial).solidsVolume;
  const double total = volumes[0] + volumes[1];
  if (!(volumes[index[0]] > 0.0 && volumes[index[1]] > 0.0)) {
    out.problems.push_back(
        {"/segregation", "the initial regions must hold both phases (small and large) to define x_small"});
  } else {
    out.segregation = Segregation{index[0], index[1], volumes[index[0]] / total};
  }
  return out;
}

}  // namespace grainbridge::mfm
