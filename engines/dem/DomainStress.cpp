#include "engines/dem/DomainStress.hpp"

#include <unordered_map>

namespace grainbridge::dem {

Mat3 wholeDomainStress(const core::data::ParticleFrame& f, double volume) {
  // Fluctuations about the mean peculiar velocity v - u(r): under Lees-Edwards shear u is the
  // imposed streaming profile u_x = shear rate (y - y_mid), zero otherwise. (The mean of v
  // itself would carry shear rate (<y> - y_mid) whenever the mass centre is off mid-height.)
  const double yMid = 0.5 * (f.domain.lo[1] + f.domain.hi[1]);
  auto peculiar = [&](std::size_t i) {
    Vec3 v = f.velocity[i];
    v[0] -= f.domain.leesEdwardsShearRate * (f.position[i][1] - yMid);
    return v;
  };
  Vec3 momentum = Vec3::Zero();
  double mass = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    momentum += f.mass[i] * peculiar(i);
    mass += f.mass[i];
  }
  const Vec3 mean = mass > 0 ? Vec3(momentum / mass) : Vec3::Zero();
  Mat3 kinetic = Mat3::Zero();
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Vec3 c = peculiar(i) - mean;
    kinetic += f.mass[i] * c * c.transpose();
  }
  Mat3 contact = Mat3::Zero();
  for (std::size_t k = 0; k < f.contacts.size(); ++k) {
    contact += f.contacts.branch[k] * (f.contacts.forceNormal[k] + f.contacts.forceTangential[k]).transpose();
  }
  if (f.wallContacts.size() > 0) {
    std::unordered_map<std::int64_t, std::size_t> index;
    for (std::size_t i = 0; i < f.size(); ++i) index[f.id[i]] = i;
    for (std::size_t k = 0; k < f.wallContacts.size(); ++k) {
      const Vec3 branch = f.position[index.at(f.wallContacts.particle[k])] - f.wallContacts.point[k];
      contact += branch * (f.wallContacts.forceNormal[k] + f.wallContacts.forceTangential[k]).transpose();
    }
  }
  return (kinetic + contact) / volume;
}

}  // namespace grainbridge::dem
