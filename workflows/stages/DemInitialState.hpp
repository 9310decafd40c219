#pragma once
// The initial state of a `dem` run and its preparation: random insertion (after placed
// particles), a LAMMPS data file or a saved frame, and Section 6.2's two-step preparation.
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
// Runs the `preparation` phases on `sim` and restarts its clock.
void prepare(StageContext& ctx, const DemSetup& setup, dem::Simulation& sim);

}  // namespace grainbridge::workflows::stages
