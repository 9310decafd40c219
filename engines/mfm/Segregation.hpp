#pragma once
// The segregation percentage of a binary bed (Eqs. 5.23-5.25) as a run measures it: which two
// solids phases are the small and the large one, and the small particles' share of the initial
// solids volume, x_small of Eq. 5.25. s_p counts the small phase's excess low in the bed as
// positive, so small and large swapped would give it the wrong sign and no error: the roles are
// checked against the diameters here.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/engine/SetupProblem.hpp"
#include "engines/mfm/InitialRegions.hpp"
#include "engines/mfm/MultiFluidSetup.hpp"

namespace grainbridge::mfm {

// The two phases of the bed as written (the `segregation` key's small and large).
struct SegregationRoles {
  std::string small, large;
};

// The two phases (0-based among the solids) and x_small.
struct Segregation {
  std::size_t small = 0, large = 1;
  double smallShare = 0.5;
};

struct SegregationSetup {
  std::optional<Segregation> segregation;  // set when the roles hold and `measure` was asked
  std::vector<SetupProblem> problems;      // pointers below the params: /segregation[/small|/large]
  std::vector<SetupProblem> warnings;      // equal diameters: the sign set by the names alone
};

// The phases `roles` names among `setup`'s solids, checked; with `measure` (the set-up and the
// initial state have no problems) x_small from the initial regions.
[[nodiscard]] SegregationSetup segregationOf(const SegregationRoles& roles, const MultiFluidSetup& setup,
                                             const InitialState& initial, bool measure);

}  // namespace grainbridge::mfm
