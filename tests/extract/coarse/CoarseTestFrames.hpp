#pragma once
// Hand-built particle frames for coarse-graining tests: particles and contacts with every array
// of the data model filled (validate() checks their lengths).
#include <cmath>
#include <cstdint>

#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::coarse::testing {

inline void addParticle(core::data::ParticleFrame& f, std::int64_t id, std::int32_t species, double radius, double mass,
                        const Vec3& position, const Vec3& velocity) {
  f.id.push_back(id);
  f.species.push_back(species);
  f.radius.push_back(radius);
  f.mass.push_back(mass);
  f.position.push_back(position);
  f.velocity.push_back(velocity);
  f.angularVelocity.push_back(Vec3::Zero());
}

// Contact between particles i and j: branch r_i - r_j (minimum image), forces on i from j.
inline void addContact(core::data::ParticleFrame& f, std::int64_t i, std::int64_t j, const Vec3& branch,
                       const Vec3& normal, const Vec3& tangential = Vec3::Zero()) {
  auto& c = f.contacts;
  c.i.push_back(i);
  c.j.push_back(j);
  c.branch.push_back(branch);
  c.contactPoint.push_back(Vec3::Zero());
  c.forceNormal.push_back(normal);
  c.forceTangential.push_back(tangential);
  c.forceNormalElastic.push_back(normal);
  c.forceNormalDissipative.push_back(Vec3::Zero());
  c.forceTangentialElastic.push_back(tangential);
  c.forceTangentialDissipative.push_back(Vec3::Zero());
}

inline double sphereVolume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }

}  // namespace grainbridge::extract::coarse::testing
