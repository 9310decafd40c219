#pragma once
// Eq. 2.3 of the reference over a whole frame, the one implementation the DEM engine's series and
// extract's domain averages share:
//   sigma = (1/V) sum_i [ m_i C_i C_i + sum_{j != i} 1/2 r_ij F_ij ],
// returned as the two sums before the division by V (callers keep their own V and, for the
// granular temperature, the kinetic sum). Each particle pair is stored once, so its two halves
// add to r_ij F_ij; a wall contact counts with the wall as j at the contact point (branch
// r_i - contact point, full length). C_i is the velocity about the streaming profile
// (StreamingProfile.hpp; zero without Lees-Edwards shear) less the mass-weighted mean of those
// peculiar velocities. Positive in compression (r_ij F_ij > 0 for repulsion), as the reference.
#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::core::data {

struct StressSums {
  Mat3 kinetic = Mat3::Zero();  // sum_i m_i C_i C_i [kg m^2/s^2]
  Mat3 contact = Mat3::Zero();  // sum over contacts r_ij F_ij [N m]
  double mass = 0.0;            // sum_i m_i [kg]
};

// Throws grainbridge::Error for a wall contact naming a particle the frame does not hold.
[[nodiscard]] StressSums wholeDomainStressSums(const ParticleFrame& frame);

}  // namespace grainbridge::core::data
