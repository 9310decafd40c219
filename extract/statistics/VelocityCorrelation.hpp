#pragma once
// Spatial correlation of particle velocity fluctuations (Section 8.2.1.1 asks for it alongside
// the force correlation of Eq. 6.12), in the same pair form with particle centres as points:
//   F_v(r) = sum_{i<j} delta(r_ij - r) C_i . C_j / sum_{i<j} delta(r_ij - r),
// and normalised by <|C|^2> (the mean of C is zero by construction): C_v(r) = F_v(r) / <|C|^2>,
// which is the `normalised` field of the result.
#include <span>

#include "core/data/ParticleFrame.hpp"
#include "extract/statistics/PairCorrelation.hpp"
#include "extract/statistics/VelocityFluctuations.hpp"

namespace grainbridge::extract::statistics {

// `accumulator` must use FrameNormalisation::SubtractMean.
void addVelocityFrame(CorrelationAccumulator& accumulator, const core::data::ParticleFrame& frame,
                      const VelocityFluctuationOptions& selection = {});

CorrelationFunction velocityCorrelation(std::span<const core::data::ParticleFrame> frames,
                                        const CorrelationOptions& options,
                                        const VelocityFluctuationOptions& selection = {});

}  // namespace grainbridge::extract::statistics
