#include "extract/coarse/DissipationRate.hpp"

#include <string>

#include "core/Error.hpp"
#include "extract/coarse/ParticleContacts.hpp"

namespace grainbridge::extract::coarse {

double contactDissipationPower(const core::data::ParticleFrame& frame, std::size_t k, std::size_t i, std::size_t j) {
  const auto& c = frame.contacts;
  const Vec3 ri = frame.position[i];
  const Vec3 rjImage = ri - c.branch[k];
  Vec3 vj = frame.velocity[j];
  vj.x() +=
      frame.domain.leesEdwardsShearRate * (rjImage.y() - frame.position[j].y());  // zero unless across the LE boundary
  const Vec3 ui = frame.velocity[i] + frame.angularVelocity[i].cross(c.contactPoint[k] - ri);
  const Vec3 uj = vj + frame.angularVelocity[j].cross(c.contactPoint[k] - rjImage);
  const Vec3 dissipative = c.forceNormalDissipative[k] + c.forceTangentialDissipative[k];
  return -dissipative.dot(ui - uj);
}

double dissipationRate(const core::data::ParticleFrame& frame, double volume) {
  if (!(volume > 0.0)) throw Error("dissipation rate: sample volume " + std::to_string(volume) + " is not positive");
  const ParticleIndex index(frame);
  const auto& c = frame.contacts;
  double power = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    power += contactDissipationPower(frame, k, index.at(c.i[k], "dissipation rate: contact", k),
                                     index.at(c.j[k], "dissipation rate: contact", k));
  }
  return power / volume;
}

}  // namespace grainbridge::extract::coarse
