#include "extract/statistics/VelocityCorrelation.hpp"

namespace grainbridge::extract::statistics {

void addVelocityFrame(CorrelationAccumulator& accumulator, const core::data::ParticleFrame& frame,
                      const VelocityFluctuationOptions& selection) {
  const VelocityFluctuations c = velocityFluctuations(frame, selection);
  // Already about the frame mean; SubtractMean re-centres each jackknife replicate.
  accumulator.add(frame.domain, c.position, c.fluctuation);
}

CorrelationFunction velocityCorrelation(std::span<const core::data::ParticleFrame> frames,
                                        const CorrelationOptions& options,
                                        const VelocityFluctuationOptions& selection) {
  CorrelationAccumulator acc(options, FrameNormalisation::SubtractMean, "velocity correlation");
  for (const auto& frame : frames) addVelocityFrame(acc, frame, selection);
  return acc.result();
}

}  // namespace grainbridge::extract::statistics
