#pragma once
// The `tfdem` stage's wiring of its set-up: the engine's (tfdem::TfdemSetup reads the gas and
// coupling keys and checks the coupling's rules), the particles from the keys tfdem shares with
// the `dem` stage (the gas's domain their box, plane walls of the `wall` material on every side it
// has, random insertion), the initial gas and the run's schedule, with every problem at the JSON
// pointer of the key at fault (below /params). The stage's config check and its run both call it.
#include <cstdint>
#include <nlohmann/json.hpp>

#include "core/engine/SetupProblem.hpp"
#include "engines/fluid/BedMeasures.hpp"
#include "engines/tfdem/TfdemEngine.hpp"
#include "workflows/stages/DemInitialState.hpp"
#include "workflows/stages/DemSetup.hpp"
#include "workflows/stages/FluidSchema.hpp"

namespace grainbridge::workflows::stages {

struct TfdemStageSetup {
  tfdem::TfdemSetup engine;
  DemSetup dem;               // species, contact timings, materials
  InsertionChoice insertion;  // insert_lo/hi and seed: the particles start at rest, at random
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
