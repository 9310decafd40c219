#pragma once
// Force-force correlation function, Eq. 6.12:
//   F(r) = sum_i sum_{j>i} delta(r_ij - r) f_i f_j / sum_i sum_{j>i} delta(r_ij - r),
// where, as the reference states, i and j are contacts, r_ij the distance between the contact
// points (minimum image on periodic axes) and f_i = F_n,i / <F_n> the normalised normal force
// of contact i. Only repulsive contacts (F_n > 0) take part and <F_n> is taken per frame over
// them (NormalForces.hpp), so each frame's <f> = 1 and uncorrelated forces give F(r) = 1.
#include <span>

#include "core/data/ParticleFrame.hpp"
#include "extract/statistics/PairCorrelation.hpp"

namespace grainbridge::extract::statistics {

// Adds one frame's contacts to `accumulator`, which must have been made with
// FrameNormalisation::DivideByMean (scalar weights F_n at the contact points, divided by the
// frame's <F_n>). Throws grainbridge::Error if the frame has no repulsive contact.
void addForceFrame(CorrelationAccumulator& accumulator, const core::data::ParticleFrame& frame);

// Eq. 6.12 pooled over frames; errors by jackknife over frames when there are several.
CorrelationFunction forceCorrelation(std::span<const core::data::ParticleFrame> frames,
                                     const CorrelationOptions& options);

}  // namespace grainbridge::extract::statistics
