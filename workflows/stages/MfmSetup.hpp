#pragma once
// The `mfm` stage's wiring of its set-up: the engine's set-up (mfm::MultiFluidSetup, which reads
// the stage's keys and lists the physics rules' problems itself), the initial regions, the DEM
// closure tables and mu(I) rheology the run reads, the schedule, the pressure taps and the
// segregation measure, with every problem at the JSON pointer of the key at fault (below /params).
// The stage's config check and its run both call it, so both see the same numbers.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/LoadedClosureTable.hpp"
#include "core/LoadedRheology.hpp"
#include "core/engine/SetupProblem.hpp"
#include "engines/mfm/InitialRegions.hpp"
#include "engines/mfm/MfmEngine.hpp"
#include "engines/mfm/Segregation.hpp"
#include "workflows/stages/FluidSchema.hpp"
#include "workflows/stages/OutputSchedule.hpp"
#include "workflows/stages/PlannedOutput.hpp"

namespace grainbridge::workflows::stages {

struct MfmSetup {
  mfm::MultiFluidSetup engine;
  mfm::InitialState initial;
  std::vector<PressureTap> taps;
  RunSchedule schedule;
  std::optional<mfm::Segregation> segregation;
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
