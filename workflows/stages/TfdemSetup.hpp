#pragma once
// Turns the `tfdem` stage's resolved parameters (SI) into the TF-DEM engine's setup (particles,
// gas grid and patches, coupling choices), the initial gas and the run's schedule, and lists what
// must stop a run before its first step, each at the JSON pointer of the key at fault (below
// /params). The particle keys are the `dem` stage's and are turned into a `dem` params object
// (the box the gas's domain, plane walls on every side of the `wall` material) so the same code
// builds the particles' materials and checks their contact times; the gas keys are the `mfm`
// stage's, checked by the fluid set-up with the fixed step fluid_dt. The stage's config check and
// its run both call it.
#include <cstdint>
#include <nlohmann/json.hpp>

#include "core/engine/SetupProblem.hpp"
#include "engines/fluid/BedMeasures.hpp"
#include "engines/tfdem/TfdemEngine.hpp"
#include "workflows/stages/DemSetup.hpp"
#include "workflows/stages/FluidSchema.hpp"

namespace grainbridge::workflows::stages {

struct TfdemStageSetup {
  tfdem::TfdemSetup engine;
  DemSetup dem;                // species, contact timings, materials
  nlohmann::json demParams;    // the `dem` params the particle keys make (insertion reads them)
  Vec3 initialGasVelocity = Vec3::Zero();
  double initialPressure = 101325.0;  // the first pressure outlet's, else atmospheric
  std::vector<PressureTap> taps;
  fluid::VerticalAxis vertical;
  double bottom = 0.0;  // the bottom's coordinate along the vertical axis
  double duration = 0.0, averageFrom = 0.0, averageTo = 0.0, outputInterval = 0.0, settleDuration = 0.0;
  std::int64_t steps = 0;        // gas steps of the run
  std::int64_t settleSteps = 0;  // gas-step-long stretches of the settling (DEM alone)
  std::int64_t seriesRows = 0;   // one per output interval
  std::vector<core::engine::SetupProblem> problems;  // below /params; empty when the run may start
};

// Assumes individually valid parameters (the schema's checks passed).
TfdemStageSetup makeTfdemSetup(const nlohmann::json& params);

}  // namespace grainbridge::workflows::stages
