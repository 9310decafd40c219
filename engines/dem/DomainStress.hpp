#pragma once
// The whole-domain stress the engine writes per step in its series: Eq. 2.3 over the box volume
// V, sigma = (sum m C C + sum r_ij F_ij) / V, from core's one implementation of the sums
// (core/data/WholeDomainStress.hpp, which extract's domain averages use too). Positive in
// compression, as in the reference.
#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::dem {
Mat3 wholeDomainStress(const core::data::ParticleFrame& frame, double volume);
}  // namespace grainbridge::dem
