#include "extract/statistics/VelocityFluctuations.hpp"

#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::statistics {

VelocityFluctuations velocityFluctuations(const core::data::ParticleFrame& frame,
                                          const VelocityFluctuationOptions& options) {
  const std::string where = "in frame at step " + std::to_string(frame.step);
  if (frame.velocity.size() != frame.size() || frame.position.size() != frame.size() ||
      (options.species && frame.species.size() != frame.size())) {
    throw Error("velocity statistics: particle arrays of unequal length " + where);
  }
  VelocityFluctuations out;
  const double yMid = 0.5 * (frame.domain.lo[1] + frame.domain.hi[1]);
  const double rate = frame.domain.leesEdwardsShearRate;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    if (options.species && frame.species[i] != *options.species) continue;
    Vec3 u = frame.velocity[i];
    u[0] -= rate * (frame.position[i][1] - yMid);  // streaming profile of simple shear
    if (!u.allFinite())
      throw Error("velocity statistics: particle id " + std::to_string(frame.id[i]) + " has a non-finite velocity " +
                  where);
    out.particle.push_back(i);
    out.position.push_back(frame.position[i]);
    out.fluctuation.push_back(u);
    out.mean += u;
  }
  if (out.particle.size() < 2) {
    throw Error("velocity statistics: " + std::to_string(out.particle.size()) + " particle(s) selected " + where +
                (options.species ? " for species " + std::to_string(*options.species) : std::string()) +
                "; need at least 2");
  }
  out.mean /= static_cast<double>(out.particle.size());
  for (Vec3& c : out.fluctuation) c -= out.mean;
  return out;
}

}  // namespace grainbridge::extract::statistics
