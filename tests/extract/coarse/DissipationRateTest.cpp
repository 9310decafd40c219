// Dissipation rate of a frame from the contacts' dissipative force parts: the power they take
// out of the relative motion at the contact point, rotation and Lees-Edwards images included.
#include "extract/coarse/DissipationRate.hpp"

#include <gtest/gtest.h>

#include "core/Error.hpp"

using namespace grainbridge;
using grainbridge::core::data::ParticleFrame;

namespace {

// Two unit-mass spheres of diameter 1 touching along x (i at the origin, j at x = 1) in a 10^3
// periodic box, with one contact whose dissipative parts the test sets.
ParticleFrame pair(const Vec3& normalDissipative, const Vec3& tangentialDissipative) {
  ParticleFrame f;
  f.domain.lo = Vec3::Zero();
  f.domain.hi = Vec3(10, 10, 10);
  f.domain.periodic = {true, true, true};
  f.id = {7, 9};
  f.species = {0, 0};
  f.radius = {0.5, 0.5};
  f.mass = {1.0, 1.0};
  f.position = {Vec3(2, 5, 5), Vec3(3, 5, 5)};
  f.velocity = {Vec3::Zero(), Vec3::Zero()};
  f.angularVelocity = {Vec3::Zero(), Vec3::Zero()};
  auto& c = f.contacts;
  c.i = {7};
  c.j = {9};
  c.branch = {Vec3(-1, 0, 0)};
  c.contactPoint = {Vec3(2.5, 5, 5)};
  c.forceNormalDissipative = {normalDissipative};
  c.forceTangentialDissipative = {tangentialDissipative};
  c.forceNormalElastic = {Vec3(-100, 0, 0)};  // elastic parts do no net work over a contact
  c.forceTangentialElastic = {Vec3(0, 40, 0)};
  c.forceNormal = {c.forceNormalElastic[0] + normalDissipative};
  c.forceTangential = {c.forceTangentialElastic[0] + tangentialDissipative};
  return f;
}

}  // namespace

TEST(DissipationRate, HeadOnDashpotTakesForceTimesApproachSpeed) {
  // Approaching at 2 m/s; the dashpot pushes i away from j (-x) with 5 N: 10 W.
  auto f = pair(Vec3(-5, 0, 0), Vec3::Zero());
  f.velocity = {Vec3(1, 0, 0), Vec3(-1, 0, 0)};
  EXPECT_DOUBLE_EQ(extract::coarse::dissipationRate(f, 2.0), 10.0 / 2.0);
}

TEST(DissipationRate, RotationEntersThroughTheContactPointVelocity) {
  // Equal spins about z: the contact points move in opposite y directions, relative speed w d.
  auto f = pair(Vec3::Zero(), Vec3(0, -3, 0));
  const double w = 4.0;
  f.angularVelocity = {Vec3(0, 0, w), Vec3(0, 0, w)};
  EXPECT_DOUBLE_EQ(extract::coarse::dissipationRate(f, 1.0), 3.0 * w * 1.0);
  // Rolling without slip (opposite spins, no relative motion at the contact) dissipates nothing.
  f.angularVelocity = {Vec3(0, 0, w), Vec3(0, 0, -w)};
  EXPECT_DOUBLE_EQ(extract::coarse::dissipationRate(f, 1.0), 0.0);
}

TEST(DissipationRate, APairAcrossTheLeesEdwardsBoundarySeesTheImageVelocity) {
  auto f = pair(Vec3(0, 0, 0), Vec3(2, 0, 0));
  f.domain.leesEdwardsShearRate = 0.5;
  f.domain.leesEdwardsOffset = 0.0;
  // i just below the top, j just above the bottom: j's image is at y + 10 and streams at +5 in x.
  f.position = {Vec3(2, 9.7, 5), Vec3(2, 0.2, 5)};
  f.contacts.branch = {Vec3(0, -0.5, 0)};
  f.contacts.contactPoint = {Vec3(2, 9.95, 5)};
  // Both at rest: relative velocity of i against the image is -5 in x; the dissipative force on
  // i opposes it (+2 N): 10 W.
  EXPECT_DOUBLE_EQ(extract::coarse::dissipationRate(f, 1.0), 10.0);
}

TEST(DissipationRate, AContactNamingAMissingParticleIsAnError) {
  auto f = pair(Vec3(-5, 0, 0), Vec3::Zero());
  f.contacts.j = {11};
  EXPECT_THROW((void)extract::coarse::dissipationRate(f, 1.0), Error);
  EXPECT_THROW((void)extract::coarse::dissipationRate(pair(Vec3::Zero(), Vec3::Zero()), 0.0), Error);
}
