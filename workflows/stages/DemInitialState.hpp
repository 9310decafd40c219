#pragma once
// The initial state of a `dem` run and its preparation: random insertion (after placed
// particles), a LAMMPS data file or a saved frame, and Section 6.2's two-step preparation.
#include <chrono>
#include <functional>
#include <nlohmann/json.hpp>

#include "engines/dem/Simulation.hpp"
#include "workflows/stages/DemSetup.hpp"
#include "workflows/stages/StageContext.hpp"

namespace grainbridge::workflows::stages {

// Every species at random without overlap, placed particles first (ids 0..).
dem::Particles insertSpecies(StageContext& ctx, const DemSetup& setup);
// Atoms of a LAMMPS data file, types mapped to species by lammps_types.
dem::Particles readLammpsParticles(const nlohmann::json& params, const DemSetup& setup);
// Particles of a saved frame, species by index.
dem::Particles readFrameParticles(const nlohmann::json& params, const DemSetup& setup);
// How the preparation saves its progress: `save` writes a checkpoint of the engine state, at
// most every `every` and when a stop is requested.
struct PreparationCheckpoints {
  std::function<void()> save;
  std::chrono::duration<double> every{std::chrono::duration<double>::max()};
};
// Runs the `preparation` phases on `sim` and restarts its clock. A `sim` restored from a
// preparation checkpoint (stepCount() > 0) continues where that checkpoint was taken.
void prepare(StageContext& ctx, const DemSetup& setup, dem::Simulation& sim, const PreparationCheckpoints& checkpoints);

}  // namespace grainbridge::workflows::stages
