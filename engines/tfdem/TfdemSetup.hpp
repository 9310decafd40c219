#pragma once
// TF-DEM's set-up (docs/engine-stages.md, section 2): the DEM particles (a dem::SimulationSetup
// and the frames' materials, which the particle keys it shares with the `dem` stage make) in a
// gas on the fluid framework (a fluid::FluidSetup with the one fixed step fluid_dt), and how the
// two are coupled. from_json reads the gas and coupling keys of the `tfdem` stage (and dt, the DEM
// step the gas step is a whole number of); the particles and their materials are set by their
// own set-up. problems() lists every rule of the coupling at the pointer of the key at fault: the
// gas step against the DEM step, what a gas patch may carry, the 2D bed's one layer of equal
// spheres, the cell edge a deposit needs. The particles' own rules are dem::SimulationSetup's.
#include <nlohmann/json.hpp>
#include <vector>

#include "core/data/FieldFrame.hpp"
#include "core/data/Materials.hpp"
#include "core/engine/SetupProblem.hpp"
#include "engines/closures/GasSolidsDrag.hpp"
#include "engines/dem/SimulationSetup.hpp"
#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/FluidSetup.hpp"
#include "engines/fluid/SimpleStep.hpp"
#include "engines/tfdem/ParticleDeposit.hpp"
#include "engines/tfdem/ParticleForces.hpp"
#include "engines/tfdem/ParticleGasModel.hpp"

namespace grainbridge::tfdem {

using core::engine::SetupProblem;

struct TfdemSetup {
  dem::SimulationSetup particles;                // its dt is the DEM step
  core::data::GridGeometry grid;                 // the gas grid (z = 1: 2D, its depth one particle diameter)
  std::vector<fluid::BoundaryPatch> boundaries;  // the gas's patches (two phases: gas, particles)
  Gas gas;
  closures::GasSolidsDrag drag = closures::GasSolidsDrag::byName("ergun_wen_yu");
  int substeps = 1;  // DEM steps per gas step: fluid_dt = substeps * dt
  VolumeDeposition deposition = VolumeDeposition::CentreCell;
  GasReaction gasReaction = GasReaction::CellAverage;
  ParticleForceSettings forces;     // drag transfer, gas velocity at the particle (forces.gas is set from gas)
  fluid::SimpleSettings solver;     // gravity, tolerances (packedFraction unused: the particles pack)
  core::data::Materials materials;  // stamped on every frame

  // The gas as written (from_json): its grid, patches and the fixed step fluid_dt (timeStep's
  // initial, minimum and maximum), for problems().
  fluid::FluidSetup fluid;

  [[nodiscard]] double fluidDt() const { return substeps * particles.dt; }

  // Every reason the coupled run cannot start, at the pointer of the `tfdem` key at fault; needs
  // `particles` and `materials` set. Empty when it can.
  [[nodiscard]] std::vector<SetupProblem> problems() const;
};

// The gas, the coupling and the DEM step from the `tfdem` stage's resolved params (SI); assumes
// each key passed its schema. Leaves the particles' materials, walls and species to their set-up.
void from_json(const nlohmann::json& j, TfdemSetup& s);

}  // namespace grainbridge::tfdem
