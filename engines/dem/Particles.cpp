#include "engines/dem/Particles.hpp"

#include <type_traits>

#include "core/Error.hpp"

namespace grainbridge::dem {

namespace {
template <class T>
T zeroOf() {
  if constexpr (std::is_arithmetic_v<T>)
    return T{0};
  else
    return T::Zero();
}
}  // namespace

void Particles::addOwned(std::int64_t globalId, std::int32_t speciesIndex, double a, double m, const Vec3& position,
                         const Vec3& velocity, const Vec3& angularVelocity, bool frozen) {
  GB_ASSERT(size() == nOwned, "owned particles are added before ghosts");
  // Every array grows by a zero (a new field starts at zero), then the given ones are set.
  auto grow = [](const char* /*name*/, auto& array) {
    array.push_back(zeroOf<typename std::decay_t<decltype(array)>::value_type>());
  };
  forEachParticleArray(*this, grow);
  forEachOwnedArray(*this, grow);
  const std::size_t i = nOwned++;
  id[i] = globalId;
  species[i] = speciesIndex;
  radius[i] = a;
  mass[i] = m;
  invMass[i] = frozen ? 0.0 : 1.0 / m;
  invInertia[i] = frozen ? 0.0 : 1.0 / (0.4 * m * a * a);  // solid sphere: I = 2/5 m a^2
  x[i] = position;
  v[i] = frozen ? Vec3::Zero() : velocity;
  omega[i] = frozen ? Vec3::Zero() : angularVelocity;
}

void Particles::clearGhosts() {
  forEachParticleArray(*this, [this](const char* /*name*/, auto& a) { a.resize(nOwned); });
  ghostOwner.clear();
  ghostShift.clear();
  ghostVelocityShift.clear();
  ghostShearCrossings.clear();
}

void Particles::addGhost(std::size_t owner, const Vec3& shift, const Vec3& velocityShift, std::int8_t shearCrossings) {
  forEachParticleArray(*this, [owner](const char* /*name*/, auto& a) {
    auto value = a[owner];  // a copy: push_back may reallocate
    a.push_back(value);
  });
  x.back() += shift;
  v.back() += velocityShift;
  force.back().setZero();
  torque.back().setZero();
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

void Particles::permuteOwned(const std::vector<std::size_t>& order) {
  GB_ASSERT(size() == nOwned && order.size() == nOwned, "permuteOwned needs no ghosts and a full order");
  auto permute = [&order](const char* /*name*/, auto& a) {
    std::remove_reference_t<decltype(a)> out(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) out[k] = a[order[k]];
    a.swap(out);
  };
  forEachParticleArray(*this, permute);
  forEachOwnedArray(*this, permute);
}

}  // namespace grainbridge::dem
