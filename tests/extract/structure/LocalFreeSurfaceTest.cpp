// The local free surface over one particle (the Brazil-nut "at the top" criterion of
// VALIDATION.md): which grains count as covering it, and the gap they leave.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "extract/structure/LocalFreeSurface.hpp"
#include "tests/extract/structure/StructureTestFrames.hpp"

namespace grainbridge::extract::structure {
namespace {

using core::data::ParticleFrame;
using testing::addContact;
using testing::addParticle;

constexpr double kNutRadius = 1.58;  // Table 6.1: d_L = 3.16 d0
const Vec3 kUp = Vec3::UnitZ();

// A nut (id 0) at height 10 with a grain (id 1) resting on its top.
ParticleFrame nutUnderOneGrain() {
  ParticleFrame f;
  f.domain.lo = Vec3(-10, -10, 0);
  f.domain.hi = Vec3(10, 10, 100);
  addParticle(f, 0, Vec3(0, 0, 10), kNutRadius);
  const Vec3 onTop(0, 0, 10 + kNutRadius + 0.5 - 1e-3);
  addParticle(f, 1, onTop, 0.5);
  addContact(f, 1, 0, onTop - Vec3(0, 0, 10), 1.0);
  return f;
}

TEST(LocalFreeSurface, AGrainRestingOnTheNutLeavesAGapJustUnderOneDiameter) {
  const auto s = localFreeSurface(nutUnderOneGrain(), 0, kUp);
  EXPECT_DOUBLE_EQ(s.top, 10 + kNutRadius);
  EXPECT_EQ(s.coveringGrains, 1u);
  EXPECT_NEAR(s.gap, 1.0 - 1e-3, 1e-12);
  EXPECT_LT(s.gap, 1.0);  // within 1 d0: at the top
}

TEST(LocalFreeSurface, ANutWithNothingAboveItIsItsOwnSurface) {
  ParticleFrame f = nutUnderOneGrain();
  f.position[1] = Vec3(0, 0, 10 - kNutRadius - 0.5);  // the grain moved below the nut
  const auto s = localFreeSurface(f, 0, kUp);
  EXPECT_EQ(s.coveringGrains, 0u);
  EXPECT_DOUBLE_EQ(s.gap, 0.0);
  EXPECT_DOUBLE_EQ(s.surface, s.top);
}

TEST(LocalFreeSurface, AColumnOfGrainsCountsToItsHighestTouchingGrain) {
  ParticleFrame f = nutUnderOneGrain();
  // Two more grains stacked on grain 1, off axis by less than r_P + r_j: the column is 3 d0 deep.
  for (std::int64_t id : {2, 3}) {
    const Vec3 p = f.position[static_cast<std::size_t>(id - 1)] + Vec3(0.3, 0, 0.95);
    addParticle(f, id, p, 0.5);
    addContact(f, id, id - 1, Vec3(0.3, 0, 0.95), 1.0);
  }
  const auto s = localFreeSurface(f, 0, kUp);
  EXPECT_EQ(s.coveringGrains, 3u);
  EXPECT_NEAR(s.surface, f.position[3].z() + 0.5, 1e-12);  // grain 3, the highest
  EXPECT_GT(s.gap, 2.0);
}

TEST(LocalFreeSurface, GrainsInFlightAndGrainsBesideTheFootprintDoNotCount) {
  ParticleFrame f = nutUnderOneGrain();
  // In flight above the nut: touches nothing.
  addParticle(f, 5, Vec3(0, 0, 40), 0.5);
  // Touching the wall but beside the nut's footprint: axis distance just beyond r_P + r_j.
  addParticle(f, 6, Vec3(kNutRadius + 0.5 + 1e-9, 0, 30), 0.5);
  f.domain.walls.push_back({"plane", Vec3::Zero(), Vec3::UnitX(), 0.0, Vec3::Zero()});
  f.wallContacts.particle.push_back(6);
  f.wallContacts.wall.push_back(0);
  f.wallContacts.point.push_back(Vec3::Zero());
  f.wallContacts.forceNormal.push_back(Vec3::UnitX());
  f.wallContacts.forceTangential.push_back(Vec3::Zero());
  EXPECT_EQ(localFreeSurface(f, 0, kUp).coveringGrains, 1u);
  // The same wall-touching grain inside the footprint is part of the bed above the nut.
  f.position[3] = Vec3(kNutRadius + 0.5 - 1e-3, 0, 30);
  const auto s = localFreeSurface(f, 0, kUp);
  EXPECT_EQ(s.coveringGrains, 2u);
  EXPECT_NEAR(s.surface, 30.5, 1e-12);
}

TEST(LocalFreeSurface, ThePeriodicImageOfAGrainCoversTheNut) {
  ParticleFrame f = nutUnderOneGrain();
  f.domain.periodic = {true, true, false};
  f.position[0].x() = -9.8;              // the nut near the low x face
  f.position[1] = Vec3(9.9, 0, 10 + 2);  // a grain across the face, 0.3 from the nut's axis
  const auto s = localFreeSurface(f, 0, kUp);
  EXPECT_EQ(s.coveringGrains, 1u);
  EXPECT_NEAR(s.surface, 12.5, 1e-12);
}

TEST(LocalFreeSurface, HeightsAreMeasuredAgainstGravityInAnyDirection) {
  ParticleFrame f = nutUnderOneGrain();
  for (auto& p : f.position) p = Vec3(p.z(), p.x(), p.y());  // the column now lies along +x
  f.contacts.branch[0] = Vec3(f.contacts.branch[0].z(), 0, 0);
  const auto s = localFreeSurface(f, 0, Vec3::UnitX());
  EXPECT_EQ(s.coveringGrains, 1u);
  EXPECT_NEAR(s.gap, 1.0 - 1e-3, 1e-12);
  EXPECT_EQ(localFreeSurface(f, 0, kUp).coveringGrains, 0u);  // sideways from +z
}

TEST(LocalFreeSurface, AMissingParticleOrABadDirectionIsRefused) {
  const ParticleFrame f = nutUnderOneGrain();
  EXPECT_THAT([&] { localFreeSurface(f, 42, kUp); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("no particle 42")));
  EXPECT_THAT([&] { localFreeSurface(f, 0, Vec3(0, 0, 2)); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("unit vector")));
}

}  // namespace
}  // namespace grainbridge::extract::structure
