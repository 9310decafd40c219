#include "engines/dem/Particles.hpp"

#include "core/Error.hpp"

namespace grainbridge::dem {

void Particles::addOwned(std::int64_t globalId, std::int32_t speciesIndex, double a, double m, const Vec3& position,
                         const Vec3& velocity, const Vec3& angularVelocity, bool frozen) {
  GB_ASSERT(size() == nOwned, "owned particles are added before ghosts");
  id.push_back(globalId);
  species.push_back(speciesIndex);
  radius.push_back(a);
  mass.push_back(m);
  invMass.push_back(frozen ? 0.0 : 1.0 / m);
  invInertia.push_back(frozen ? 0.0 : 1.0 / (0.4 * m * a * a));  // solid sphere: I = 2/5 m a^2
  x.push_back(position);
  v.push_back(frozen ? Vec3::Zero() : velocity);
  omega.push_back(frozen ? Vec3::Zero() : angularVelocity);
  force.push_back(Vec3::Zero());
  torque.push_back(Vec3::Zero());
  couplingA.push_back(Vec3::Zero());
  couplingB.push_back(0.0);
  couplingU.push_back(Vec3::Zero());
  ++nOwned;
}

void Particles::clearGhosts() {
  for (auto* a : {&radius, &mass, &invMass, &invInertia}) a->resize(nOwned);
  for (auto* a : {&x, &v, &omega, &force, &torque}) a->resize(nOwned);
  id.resize(nOwned);
  species.resize(nOwned);
  ghostOwner.clear();
  ghostShift.clear();
  ghostVelocityShift.clear();
  ghostShearCrossings.clear();
}

void Particles::addGhost(std::size_t owner, const Vec3& shift, const Vec3& velocityShift, std::int8_t shearCrossings) {
  id.push_back(id[owner]);
  species.push_back(species[owner]);
  radius.push_back(radius[owner]);
  mass.push_back(mass[owner]);
  invMass.push_back(invMass[owner]);
  invInertia.push_back(invInertia[owner]);
  x.push_back(x[owner] + shift);
  v.push_back(v[owner] + velocityShift);
  omega.push_back(omega[owner]);
  force.push_back(Vec3::Zero());
  torque.push_back(Vec3::Zero());
  ghostOwner.push_back(owner);
  ghostShift.push_back(shift);
  ghostVelocityShift.push_back(velocityShift);
  ghostShearCrossings.push_back(shearCrossings);
}

void Particles::refreshGhosts(double shearDrift) {
  for (std::size_t k = 0; k < ghostOwner.size(); ++k) {
    const std::size_t g = nOwned + k;
    const std::size_t o = ghostOwner[k];
    x[g] = x[o] + ghostShift[k];
    x[g][0] += ghostShearCrossings[k] * shearDrift;
    v[g] = v[o] + ghostVelocityShift[k];
    omega[g] = omega[o];
  }
}

namespace {
template <class T>
void permute(std::vector<T>& a, const std::vector<std::size_t>& order) {
  std::vector<T> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[k] = a[order[k]];
  a.swap(out);
}
}  // namespace

void Particles::permuteOwned(const std::vector<std::size_t>& order) {
  GB_ASSERT(size() == nOwned && order.size() == nOwned, "permuteOwned needs no ghosts and a full order");
  permute(id, order);
  permute(species, order);
  permute(radius, order);
  permute(mass, order);
  permute(invMass, order);
  permute(invInertia, order);
  permute(x, order);
  permute(v, order);
  permute(omega, order);
  permute(force, order);
  permute(torque, order);
  permute(couplingA, order);
  permute(couplingB, order);
  permute(couplingU, order);
}

}  // namespace grainbridge::dem
