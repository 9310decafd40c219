#pragma once
// Whole-domain stress of a frame by Eq. 2.3 of the reference,
//   sigma = (1/V) sum_i [ m_i C_i C_i + sum_{j != i} 1/2 r_ij F_ij ],
// which the engine writes per step in its series. Each particle pair is stored once, so its
// two halves add to r_ij F_ij; a wall contact counts with the wall as j at the contact point
// (branch r_i - contact point, full length). C_i is the velocity about the mean of the mobile
// particles, and under Lees-Edwards shear also about the streaming profile
// u_x = shear rate (y - y_mid). Sign: positive in compression (r_ij F_ij > 0 for repulsion), as in the reference.
#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::dem {
Mat3 wholeDomainStress(const core::data::ParticleFrame& frame, double volume);
}  // namespace grainbridge::dem
