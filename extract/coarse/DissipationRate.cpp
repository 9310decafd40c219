#include "extract/coarse/DissipationRate.hpp"

#include <string>
#include <unordered_map>

#include "core/Error.hpp"

namespace grainbridge::extract::coarse {

double dissipationRate(const core::data::ParticleFrame& frame, double volume) {
  if (!(volume > 0.0)) throw Error("dissipation rate: sample volume " + std::to_string(volume) + " is not positive");
  std::unordered_map<std::int64_t, std::size_t> indexOf;
  indexOf.reserve(frame.size());
  for (std::size_t k = 0; k < frame.size(); ++k) indexOf.emplace(frame.id[k], k);
  auto index = [&](std::int64_t id, std::size_t contact) {
    const auto it = indexOf.find(id);
    if (it == indexOf.end()) {
      throw Error("dissipation rate: contact " + std::to_string(contact) + " of the frame at step " +
                  std::to_string(frame.step) + " names particle " + std::to_string(id) + ", which the frame lacks");
    }
    return it->second;
  };
  const auto& c = frame.contacts;
  const double shearRate = frame.domain.leesEdwardsShearRate;
  double power = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const std::size_t i = index(c.i[k], k);
    const std::size_t j = index(c.j[k], k);
    const Vec3 ri = frame.position[i];
    const Vec3 rjImage = ri - c.branch[k];
    Vec3 vj = frame.velocity[j];
    vj.x() += shearRate * (rjImage.y() - frame.position[j].y());  // zero unless across the LE boundary
    const Vec3 ui = frame.velocity[i] + frame.angularVelocity[i].cross(c.contactPoint[k] - ri);
    const Vec3 uj = vj + frame.angularVelocity[j].cross(c.contactPoint[k] - rjImage);
    const Vec3 dissipative = c.forceNormalDissipative[k] + c.forceTangentialDissipative[k];
    power -= dissipative.dot(ui - uj);
  }
  return power / volume;
}

}  // namespace grainbridge::extract::coarse
