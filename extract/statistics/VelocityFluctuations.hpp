#pragma once
// Particle velocity fluctuations C_i = u_i - <u>, the peculiar velocities of Section 8.2.1.1's
// single-particle distribution and of the velocity correlation. Under Lees-Edwards shear u_i is
// the velocity about the imposed streaming profile, u_i = v_i - gammadot (y_i - y_mid) e_x, as in
// the whole-domain stress (core/data/WholeDomainStress.hpp). The mean is over particles (number
// weighted), so the C_i of the selection sum to zero; for a mixture select one species, since
// species in a mixture need not share a temperature.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::statistics {

struct VelocityFluctuationOptions {
  std::optional<std::int32_t> species;  // all particles when empty
};

struct VelocityFluctuations {
  std::vector<std::size_t> particle;  // index into the frame's arrays
  std::vector<Vec3> position;
  std::vector<Vec3> fluctuation;  // C_i, in the frame's velocity unit
  Vec3 mean = Vec3::Zero();       // <u> that was removed
};

// Throws grainbridge::Error naming the step when fewer than two particles are selected.
VelocityFluctuations velocityFluctuations(const core::data::ParticleFrame& frame,
                                          const VelocityFluctuationOptions& options = {});

}  // namespace grainbridge::extract::statistics
