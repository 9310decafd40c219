#pragma once
// The solids-solids drag pairs of a mixture (Eq. 3.18). Every pair of solids phases exchanges
// momentum: a pair a config does not list takes the friction coefficient C_f 0 and e_lm the mean
// of the two phases' restitution (e, not e_eff, with the rotation model); a listed pair names its
// two phases and sets C_f and, if it gives one, e_lm. The phases' names must then be unique.
#include <optional>
#include <string>
#include <vector>

#include "core/engine/SetupProblem.hpp"
#include "engines/mfm/MultiFluidModel.hpp"

namespace grainbridge::mfm {

struct SolidsPairRequest {
  std::vector<std::string> phases;  // two names of `solids` entries
  double friction = 0.0;            // C_f
  std::optional<double> restitution;
};

struct SolidsPairsResult {
  std::vector<SolidsPair> pairs;  // every pair l < m (1-based phases), in order (1,2), (1,3), ..., (2,3), ...
  // Pointers "/solids/<k>/name" (a name used twice) and "/solids_pairs/<k>[/phases[/<i>]]".
  std::vector<core::engine::SetupProblem> problems;
};

[[nodiscard]] SolidsPairsResult solidsPairsFor(const std::vector<SolidsPhase>& solids,
                                               const std::vector<SolidsPairRequest>& requests);

}  // namespace grainbridge::mfm
