#include "extract/statistics/ForceCorrelation.hpp"

#include <string>

#include "core/Error.hpp"
#include "extract/statistics/NormalForces.hpp"

namespace grainbridge::extract::statistics {

void addForceFrame(CorrelationAccumulator& accumulator, const core::data::ParticleFrame& frame) {
  const RepulsiveForces forces = repulsiveForces(frame);
  // Raw F_n: the accumulator divides by the frame mean itself (FrameNormalisation::DivideByMean),
  // also inside each jackknife replicate.
  accumulator.add(frame.domain, forces.contactPoint, forces.normalForce);
}

CorrelationFunction forceCorrelation(std::span<const core::data::ParticleFrame> frames,
                                     const CorrelationOptions& options) {
  CorrelationAccumulator acc(options, FrameNormalisation::DivideByMean, "force correlation (Eq. 6.12)");
  for (const auto& frame : frames) addForceFrame(acc, frame);
  return acc.result();
}

}  // namespace grainbridge::extract::statistics
