#pragma once
// Per-component moments of the particle velocity fluctuations (Section 8.2.1.1): variance
// <C_a^2> (so that T = (<C_x^2> + <C_y^2> + <C_z^2>)/3, Eq. 3.38, when all particles have one
// mass), skewness and kurtosis <C_a^4>/<C_a^2>^2, which is 3 for the Maxwellian of KTGF.
// Fluctuations as in VelocityFluctuations.hpp; frames are pooled, each about its own mean.
#include <array>
#include <cstddef>
#include <span>

#include "core/data/ParticleFrame.hpp"
#include "extract/statistics/SampleMoments.hpp"
#include "extract/statistics/VelocityFluctuations.hpp"

namespace grainbridge::extract::statistics {

struct VelocityMoments {
  std::array<SampleMoments, 3> component;  // x, y, z; variance in (velocity unit)^2
  std::size_t samples = 0;                 // particle-frames pooled
  std::size_t frames = 0;
};

// Errors treat the pooled particle velocities as independent samples. A component without spread
// (a planar run) gets variance 0 and NaN skewness and kurtosis.
VelocityMoments velocityMoments(std::span<const core::data::ParticleFrame> frames,
                                const VelocityFluctuationOptions& selection = {});

}  // namespace grainbridge::extract::statistics
