#include "extract/statistics/ContactSubset.hpp"

#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::statistics {

core::data::ParticleFrame withContacts(const core::data::ParticleFrame& frame, std::span<const std::size_t> keep) {
  core::data::ParticleFrame out = frame;
  const auto& from = frame.contacts;
  auto& to = out.contacts;
  to = {};
  for (const std::size_t k : keep) {
    if (k >= from.size()) {
      throw Error("contact subset: index " + std::to_string(k) + " is beyond the " + std::to_string(from.size()) +
                  " contacts of the frame at step " + std::to_string(frame.step));
    }
    to.i.push_back(from.i[k]);
    to.j.push_back(from.j[k]);
    to.branch.push_back(from.branch[k]);
    to.contactPoint.push_back(from.contactPoint[k]);
    to.forceNormal.push_back(from.forceNormal[k]);
    to.forceTangential.push_back(from.forceTangential[k]);
    to.forceNormalElastic.push_back(from.forceNormalElastic[k]);
    to.forceNormalDissipative.push_back(from.forceNormalDissipative[k]);
    to.forceTangentialElastic.push_back(from.forceTangentialElastic[k]);
    to.forceTangentialDissipative.push_back(from.forceTangentialDissipative[k]);
  }
  return out;
}

}  // namespace grainbridge::extract::statistics
