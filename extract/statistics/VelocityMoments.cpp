#include "extract/statistics/VelocityMoments.hpp"

#include <limits>
#include <vector>

#include "core/Error.hpp"

namespace grainbridge::extract::statistics {

VelocityMoments velocityMoments(std::span<const core::data::ParticleFrame> frames,
                                const VelocityFluctuationOptions& selection) {
  if (frames.empty()) throw Error("velocity moments: no frames");
  std::array<std::vector<double>, 3> c;
  for (const auto& frame : frames) {
    const VelocityFluctuations v = velocityFluctuations(frame, selection);
    for (const Vec3& u : v.fluctuation) {
      for (int a = 0; a < 3; ++a) c[static_cast<std::size_t>(a)].push_back(u[a]);
    }
  }
  static const char* names[3] = {"velocity moments (x)", "velocity moments (y)", "velocity moments (z)"};
  VelocityMoments out;
  out.frames = frames.size();
  out.samples = c[0].size();
  for (std::size_t a = 0; a < 3; ++a) {
    // A planar run has no spread out of plane: report variance 0 and undefined shape moments
    // for that component rather than refusing the frame.
    bool spread = false;
    for (double x : c[a]) spread = spread || x != c[a][0];
    if (spread) {
      out.component[a] = sampleMoments(c[a], names[a]);
    } else {
      SampleMoments& m = out.component[a];
      m.samples = c[a].size();
      m.skewness = m.skewnessError = m.kurtosis = m.kurtosisError = std::numeric_limits<double>::quiet_NaN();
    }
  }
  return out;
}

}  // namespace grainbridge::extract::statistics
