// Eq. 2.3 split by species (issue 60): the parts add up to the mixture's stress, a contact's
// branch is shared at its contact point (Tunuguntla, Thornton and Weinhart 2016), a pair's totals
// need no split, and each species' temperature is about the mixture's flow.
#include "extract/coarse/SpeciesStress.hpp"

#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "core/data/WholeDomainStress.hpp"
#include "extract/coarse/DissipationRate.hpp"
#include "tests/extract/coarse/CoarseTestFrames.hpp"

using namespace grainbridge;
using grainbridge::core::data::ParticleFrame;
using namespace grainbridge::extract::coarse::testing;

namespace {

constexpr double kVolume = 1000.0;  // the 10^3 box

// Two small spheres (species 0: radius 0.5, mass 1) and one large (species 3: radius 1, mass 8) in
// a row along x: small 1 touches small 2, small 2 touches the large one. Forces on i from j push
// i away from j (compression).
ParticleFrame mixture() {
  ParticleFrame f;
  f.domain.lo = Vec3::Zero();
  f.domain.hi = Vec3(10, 10, 10);
  f.domain.periodic = {true, true, true};
  addParticle(f, 1, 0, 0.5, 1.0, Vec3(1, 5, 5), Vec3(1, 0, 0));
  addParticle(f, 2, 0, 0.5, 1.0, Vec3(2, 5, 5), Vec3(-1, 2, 0));
  addParticle(f, 3, 3, 1.0, 8.0, Vec3(3.5, 5, 5), Vec3(0.25, 0, 0));
  addContact(f, 1, 2, Vec3(-1, 0, 0), Vec3(-4, 0, 0), Vec3(0, 1, 0));
  f.contacts.contactPoint.back() = Vec3(1.5, 5, 5);
  addContact(f, 2, 3, Vec3(-1.5, 0, 0), Vec3(-10, 0, 0), Vec3(0, 3, 0));
  f.contacts.contactPoint.back() = Vec3(2.5, 5, 5);
  return f;
}

}  // namespace

TEST(SpeciesStress, PartsAddUpToTheMixturesStress) {
  const ParticleFrame f = mixture();
  const auto parts = extract::coarse::speciesStresses(f, kVolume);
  const auto whole = core::data::wholeDomainStressSums(f);
  ASSERT_EQ(parts.species.size(), 2u);
  Mat3 kinetic = Mat3::Zero(), contact = Mat3::Zero(), pairs = Mat3::Zero();
  for (const auto& s : parts.species) {
    kinetic += s.kinetic;
    contact += s.contact;
  }
  for (const auto& p : parts.pairs) pairs += p.stress;
  EXPECT_LT((kinetic - whole.kinetic / kVolume).norm(), 1e-15);
  EXPECT_LT((contact - whole.contact / kVolume).norm(), 1e-15);
  EXPECT_LT((pairs - whole.contact / kVolume).norm(), 1e-15);
}

TEST(SpeciesStress, ABranchIsSharedAtItsContactPoint) {
  const auto parts = extract::coarse::speciesStresses(mixture(), kVolume);
  const auto& small = parts.species[0];
  const auto& large = parts.species[1];
  EXPECT_EQ(small.species, 0);
  EXPECT_EQ(large.species, 3);
  EXPECT_EQ(small.particles, 2u);
  EXPECT_EQ(large.particles, 1u);
  // xx: the small-small contact r_ij F = (-1)(-4) = 4, all the small species'; the small-large
  // one (-1.5)(-10) = 15, the small sphere's radius 0.5 of it (5), the large one's 1 (10).
  EXPECT_DOUBLE_EQ(small.contact(0, 0) * kVolume, 4.0 + 5.0);
  EXPECT_DOUBLE_EQ(large.contact(0, 0) * kVolume, 10.0);
  // xy: the tangential forces along y, r_x F_y: -1 * 1 and, split, -0.5 * 3 and -1 * 3.
  EXPECT_DOUBLE_EQ(small.contact(0, 1) * kVolume, -1.0 - 1.5);
  EXPECT_DOUBLE_EQ(large.contact(0, 1) * kVolume, -3.0);
  // The pairs, (0, 0), (0, 3), (3, 3), whole.
  ASSERT_EQ(parts.pairs.size(), 3u);
  EXPECT_EQ(parts.pairs[1].first, 0);
  EXPECT_EQ(parts.pairs[1].second, 3);
  EXPECT_EQ(parts.pairs[0].contacts, 1u);
  EXPECT_EQ(parts.pairs[1].contacts, 1u);
  EXPECT_EQ(parts.pairs[2].contacts, 0u);
  EXPECT_DOUBLE_EQ(parts.pairs[0].stress(0, 0) * kVolume, 4.0);
  EXPECT_DOUBLE_EQ(parts.pairs[1].stress(0, 0) * kVolume, 15.0);
  EXPECT_DOUBLE_EQ(parts.pairs[2].stress.norm(), 0.0);
  EXPECT_DOUBLE_EQ(small.solidFraction, 2.0 * sphereVolume(0.5) / kVolume);
  EXPECT_DOUBLE_EQ(large.solidFraction, sphereVolume(1.0) / kVolume);
}

TEST(SpeciesStress, EachSpeciesTemperatureIsAboutTheMixturesFlow) {
  // Momentum (1 - 1 + 2, 2, 0) over mass 10: the mixture's mean velocity (0.2, 0.2, 0). The small
  // species' own mean is (0, 1, 0), which its temperature must not be taken about.
  const auto parts = extract::coarse::speciesStresses(mixture(), kVolume);
  const Vec3 u(0.2, 0.2, 0.0);
  const double c2small = (Vec3(1, 0, 0) - u).squaredNorm() + (Vec3(-1, 2, 0) - u).squaredNorm();
  const double c2large = 8.0 * (Vec3(0.25, 0, 0) - u).squaredNorm();
  EXPECT_NEAR(parts.species[0].granularTemperature, c2small / (3.0 * 2.0), 1e-15);
  EXPECT_NEAR(parts.species[1].granularTemperature, c2large / (3.0 * 8.0), 1e-15);
  EXPECT_DOUBLE_EQ(parts.species[0].mass, 2.0);
}

TEST(SpeciesStress, PairDissipationAddsUpToTheFramesAndWallsGoToTheirParticle) {
  ParticleFrame f = mixture();
  // The small-large pair separates at 1.25 m/s along x; its dashpot holds the small sphere back
  // with 2 N (+x, towards the large one) and takes 2.5 W.
  f.contacts.forceNormalDissipative[1] = Vec3(2, 0, 0);
  f.contacts.forceNormalElastic[1] = Vec3(-12, 0, 0);
  const auto parts = extract::coarse::speciesStresses(f, kVolume);
  EXPECT_DOUBLE_EQ(parts.pairs[1].dissipation, 2.5 / kVolume);
  EXPECT_DOUBLE_EQ(parts.pairs[0].dissipation, 0.0);
  EXPECT_DOUBLE_EQ(parts.pairs[0].dissipation + parts.pairs[1].dissipation,
                   extract::coarse::dissipationRate(f, kVolume));

  auto& w = f.wallContacts;
  w.particle.push_back(3);
  w.wall.push_back(0);
  w.point.push_back(Vec3(4.5, 5, 5));
  w.forceNormal.push_back(Vec3(-6, 0, 0));
  w.forceTangential.push_back(Vec3::Zero());
  const auto walled = extract::coarse::speciesStresses(f, kVolume);
  EXPECT_DOUBLE_EQ((walled.species[1].contact(0, 0) - parts.species[1].contact(0, 0)) * kVolume, 6.0);
  EXPECT_DOUBLE_EQ(walled.species[0].contact(0, 0), parts.species[0].contact(0, 0));
}

TEST(SpeciesStress, RefusesANonPositiveVolume) {
  EXPECT_THROW((void)extract::coarse::speciesStresses(mixture(), 0.0), Error);
}
