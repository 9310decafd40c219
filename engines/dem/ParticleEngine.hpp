#pragma once
// A particle engine as the dem stage's series columns and summary read it, whichever code runs
// the steps: grainbridge's own (DemEngine) or LAMMPS (engines/lammps/LammpsEngine). What it
// offers is the state of the last step: the frame (particles and contacts, built once per step)
// and the few quantities a frame does not carry.
#include <cstdint>
#include <vector>

#include "core/Types.hpp"
#include "core/data/Materials.hpp"
#include "core/data/ParticleFrame.hpp"
#include "core/engine/SteppedEngine.hpp"
#include "engines/dem/Energies.hpp"

namespace grainbridge::dem {

class ParticleEngine : public core::engine::SteppedEngine {
 public:
  // The current state as a frame, with the contacts of the last observed step.
  virtual const core::data::ParticleFrame& frame() = 0;
  // Kinetic energies of the mobile particles (frozen ones never move).
  [[nodiscard]] virtual Energies energies() = 0;
  [[nodiscard]] virtual std::int64_t mobileCount() = 0;
  // The force the particles exert on each wall, in the setup's wall order.
  [[nodiscard]] virtual std::vector<Vec3> wallForces() = 0;
  [[nodiscard]] virtual std::int64_t neighbourRebuilds() const = 0;
  // Species, contact coefficients and gravity stamped on every frame (set by the stage).
  virtual void setMaterials(core::data::Materials materials) = 0;
};

}  // namespace grainbridge::dem
