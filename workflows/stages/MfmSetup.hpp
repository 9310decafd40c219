#pragma once
// Turns the `mfm` stage's resolved parameters (SI) into the multi-fluid engine's setup and
// initial state, and lists what must stop a run before its first step, each at the JSON pointer
// of the parameter at fault (below /params). The stage's config check and its run both call it,
// so both see the same numbers and each rule is written once.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/LoadedClosureTable.hpp"
#include "core/LoadedRheology.hpp"
#include "core/engine/SetupProblem.hpp"
#include "engines/mfm/InitialRegions.hpp"
#include "engines/mfm/MfmEngine.hpp"
#include "workflows/stages/FluidSchema.hpp"
#include "workflows/stages/PlannedOutput.hpp"

namespace grainbridge::workflows::stages {

// The two phases of a binary bed's segregation percentage (0-based among the solids) and the
// small particles' share of the initial solids volume, x_small of Eq. 5.25.
struct Segregation {
  std::size_t small = 0, large = 1;
  double smallShare = 0.5;
};

struct MfmSetup {
  mfm::MultiFluidSetup engine;
  mfm::InitialState initial;
  std::vector<PressureTap> taps;
  double duration = 0.0;
  double averageFrom = 0.0;
  double averageTo = 0.0;  // average_to, default the duration
  std::optional<Segregation> segregation;
  // Pointers below /params: empty when the run may start.
  std::vector<core::engine::SetupProblem> problems;
  // What may run but is likely not what was meant (pointers below /params); the config check
  // logs them as warnings.
  std::vector<core::engine::SetupProblem> warnings;
};

// Assumes individually valid parameters (the schema's checks passed). `closureTables` are the
// tables a `table` closure reads (StageContext::closureTables), `rheologies` the mu(I) rheology
// `plastic` mu_i reads (StageContext::rheologies); without them (a config check) the closure is
// the kinetic theory, the plastic viscosity Schaeffer's, and only the parameters are checked.
MfmSetup makeMfmSetup(const nlohmann::json& params,
                      const std::vector<core::LoadedClosureTable>* closureTables = nullptr,
                      const std::vector<core::LoadedRheology>* rheologies = nullptr);

// Why `plastic` mu_i cannot take a rheology measured on `grains` (another diameter or density
// than the solids phase's: I would be formed with the wrong grains), or "" when it can.
[[nodiscard]] std::string rheologyGrainsProblem(const nlohmann::json& params, const Grains& grains);

// The quantity of the table each of table_quantities' names takes: p_theta, eta_theta, j_theta.
[[nodiscard]] std::string tableQuantity(const std::string& closureQuantity);

// The run's output steps: duration / interval, rounded.
[[nodiscard]] std::int64_t mfmSteps(const nlohmann::json& params);

}  // namespace grainbridge::workflows::stages
