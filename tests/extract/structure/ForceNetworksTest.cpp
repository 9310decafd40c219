// Force networks (Section 6.3.2): components of the F_n > 0 contact graph, network-averaged
// coordination, the strong subnetwork (F_n above the mean) and extents across periodic and
// Lees-Edwards boundaries.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "extract/structure/ForceNetworks.hpp"
#include "extract/structure/NetworkExtent.hpp"
#include "tests/extract/structure/StructureTestFrames.hpp"

namespace grainbridge::extract::structure {
namespace {

using core::data::ParticleFrame;
using testing::addContact;
using testing::addParticle;

// Chain A: ids 1-2-3-4 along x with F_n = 1, 2, 6. Chain B: 10-11-12 with F_n = 3 and a tensile
// -0.5 (a dashpot pulling at the end of a contact), plus 13 touching 12 with exactly zero force.
// A wall contact on 4 must not count. Counted contacts: 1, 2, 6, 3 -> mean 3, so only the
// F_n = 6 contact is strong (3 equals the mean and is not above it).
ParticleFrame twoChains() {
  ParticleFrame f;
  for (std::int64_t id : {1, 2, 3, 4}) addParticle(f, id, Vec3(0.95 * static_cast<double>(id), 0, 0), 0.5);
  for (std::int64_t id : {10, 11, 12, 13}) addParticle(f, id, Vec3(0.95 * static_cast<double>(id - 10), 5, 0), 0.5);
  const Vec3 step(-0.95, 0, 0);  // r_i - r_j for j the next particle along +x
  addContact(f, 1, 2, step, 1.0);
  addContact(f, 3, 2, -step, 2.0);  // listed in the other order
  addContact(f, 3, 4, step, 6.0);
  addContact(f, 10, 11, step, 3.0);
  addContact(f, 11, 12, step, -0.5);
  addContact(f, 12, 13, step, 0.0);
  f.domain.walls.push_back({"plane", Vec3::Zero(), Vec3::UnitY(), 0.0, Vec3::Zero()});
  f.wallContacts.particle.push_back(4);
  f.wallContacts.wall.push_back(0);
  f.wallContacts.point.push_back(Vec3::Zero());
  f.wallContacts.forceNormal.push_back(Vec3(0, 100, 0));
  f.wallContacts.forceTangential.push_back(Vec3::Zero());
  return f;
}

TEST(ForceNetworks, TwoChainsWithTensileContactGiveTheRightComponents) {
  ParticleFrame f = twoChains();
  f.wallContacts = {};
  f.domain.walls.clear();
  const ForceNetworkAnalysis r = analyzeForceNetworks(f);
  EXPECT_EQ(r.repulsiveContacts, 4u);
  EXPECT_EQ(r.excludedContacts, 2u);
  EXPECT_DOUBLE_EQ(r.meanNormalForce, 3.0);
  ASSERT_EQ(r.networks.size(), 2u);
  EXPECT_EQ(r.particlesInNetworks, 6u);

  const ForceNetwork& a = r.networks[0];
  EXPECT_EQ(a.particleIds, (std::vector<std::int64_t>{1, 2, 3, 4}));
  EXPECT_EQ(a.contacts, 3u);
  EXPECT_DOUBLE_EQ(a.coordination, 1.5);
  EXPECT_EQ(a.strongContacts, 1u);
  EXPECT_EQ(a.strongParticles, 2u);
  EXPECT_NEAR(a.extent.axisExtent.x(), 3 * 0.95, 1e-12);
  EXPECT_NEAR(a.extent.largestCentreDistance, 3 * 0.95, 1e-12);
  EXPECT_FALSE(a.extent.wrapsAroundBox);

  const ForceNetwork& b = r.networks[1];
  EXPECT_EQ(b.particleIds, (std::vector<std::int64_t>{10, 11}));  // 12 hangs on a tensile contact
  EXPECT_EQ(b.contacts, 1u);
  EXPECT_DOUBLE_EQ(b.coordination, 1.0);
  EXPECT_EQ(b.strongContacts, 0u);
  EXPECT_EQ(b.strongParticles, 0u);

  EXPECT_EQ(r.strongContacts, 1u);
  EXPECT_EQ(r.strongParticles, 2u);
  EXPECT_EQ(r.strongComponents, 1u);
  EXPECT_EQ(r.largestStrongComponent.particles, 2u);
  EXPECT_EQ(r.largestStrongComponent.contacts, 1u);
}

TEST(ForceNetworks, WallContactsDoNotCount) {
  const ForceNetworkAnalysis r = analyzeForceNetworks(twoChains());
  EXPECT_EQ(r.repulsiveContacts, 4u);
  EXPECT_DOUBLE_EQ(r.meanNormalForce, 3.0);
  EXPECT_DOUBLE_EQ(r.networks[0].coordination, 1.5);
}

TEST(ForceNetworks, StrongSubnetworkSplitsIntoComponents) {
  // Chain 1..7 with forces 5, 5, 1, 1, 5, 1: mean 3, strong = the two 5-chains {1,2,3} and {5,6}.
  ParticleFrame f;
  for (std::int64_t id = 1; id <= 7; ++id) addParticle(f, id, Vec3(0.9 * static_cast<double>(id), 0, 0), 0.5);
  const double forces[] = {5, 5, 1, 1, 5, 1};
  for (std::int64_t id = 1; id <= 6; ++id) addContact(f, id, id + 1, Vec3(-0.9, 0, 0), forces[id - 1]);
  const ForceNetworkAnalysis r = analyzeForceNetworks(f);
  ASSERT_EQ(r.networks.size(), 1u);
  EXPECT_EQ(r.strongContacts, 3u);
  EXPECT_EQ(r.strongParticles, 5u);
  EXPECT_EQ(r.strongComponents, 2u);
  EXPECT_EQ(r.largestStrongComponent.particles, 3u);
  EXPECT_EQ(r.largestStrongComponent.contacts, 2u);
  EXPECT_EQ(r.networks[0].strongParticles, 5u);
  EXPECT_DOUBLE_EQ(r.networks[0].coordination, 12.0 / 7.0);
}

// A chain crossing the periodic x boundary: stored positions 9.0, 9.9, 0.8, 1.7 in a box
// [0, 10) are one chain 2.7 long, not 8.2 wide.
TEST(ForceNetworks, ExtentOfNetworkCrossingPeriodicBoundary) {
  ParticleFrame f;
  f.domain.hi = Vec3(10, 10, 10);
  f.domain.periodic = {true, false, false};
  const std::vector<double> x{9.0, 9.9, 0.8, 1.7};
  for (std::size_t k = 0; k < x.size(); ++k) {
    addParticle(f, static_cast<std::int64_t>(k + 1), Vec3(x[k], 5.0 + 0.1 * static_cast<double>(k), 5), 0.5);
  }
  for (std::int64_t id = 1; id <= 3; ++id) addContact(f, id, id + 1, Vec3(-0.9, -0.1, 0), 1.0);
  ForceNetworkOptions options;
  options.gravity = Vec3(0, -9.81, 0);
  const ForceNetworkAnalysis r = analyzeForceNetworks(f, options);
  ASSERT_EQ(r.networks.size(), 1u);
  const NetworkExtent& e = r.networks[0].extent;
  EXPECT_NEAR(e.axisExtent.x(), 2.7, 1e-12);
  EXPECT_NEAR(e.axisExtent.y(), 0.3, 1e-12);
  EXPECT_NEAR(e.axisExtent.z(), 0.0, 1e-12);
  EXPECT_NEAR(e.gravityExtent, 0.3, 1e-12);
  EXPECT_NEAR(e.largestCentreDistance, std::hypot(2.7, 0.3), 1e-12);
  EXPECT_FALSE(e.wrapsAroundBox);
}

// Across a Lees-Edwards boundary the branch carries the x offset of the image: a pair stored at
// y = 9.8 and y = 0.3 (box height 10) with branch (0.2, -0.5, 0) is 0.5 apart in y.
TEST(ForceNetworks, ExtentAcrossLeesEdwardsBoundaryFollowsTheBranch) {
  ParticleFrame f;
  f.domain.hi = Vec3(10, 10, 10);
  f.domain.periodic = {true, true, true};
  f.domain.leesEdwardsOffset = 3.0;
  addParticle(f, 1, Vec3(5.2, 9.8, 5), 0.5);
  addParticle(f, 2, Vec3(2.0, 0.3, 5), 0.5);  // its image above is at (5.0, 10.3)
  addContact(f, 1, 2, Vec3(0.2, -0.5, 0), 1.0);
  const NetworkExtent e = analyzeForceNetworks(f).networks.at(0).extent;
  EXPECT_NEAR(e.axisExtent.x(), 0.2, 1e-12);
  EXPECT_NEAR(e.axisExtent.y(), 0.5, 1e-12);
}

// A ring of four particles around a periodic box of length 4: its cycle adds up to a box
// length, so the network touches its own image.
TEST(ForceNetworks, NetworkWrappingThroughTheBoxIsFlagged) {
  ParticleFrame f;
  f.domain.hi = Vec3(4, 4, 4);
  f.domain.periodic = {true, true, true};
  for (std::int64_t id = 0; id < 4; ++id) addParticle(f, id, Vec3(0.5 + static_cast<double>(id), 2, 2), 0.52);
  for (std::int64_t id = 0; id < 4; ++id) addContact(f, id, (id + 1) % 4, Vec3(-1, 0, 0), 1.0);
  const ForceNetworkAnalysis r = analyzeForceNetworks(f);
  ASSERT_EQ(r.networks.size(), 1u);
  EXPECT_TRUE(r.networks[0].extent.wrapsAroundBox);
  EXPECT_DOUBLE_EQ(r.networks[0].coordination, 2.0);
}

TEST(NetworkExtent, LargestCentreDistanceMatchesAllPairs) {
  std::mt19937_64 rng(21);
  std::normal_distribution<double> normal(0.0, 1.0);
  // A random tree over a lumpy cloud: member k hangs from a random earlier member.
  const std::size_t n = 600;
  std::vector<Vec3> u(n, Vec3::Zero());
  std::vector<ExtentEdge> edges;
  for (std::size_t k = 1; k < n; ++k) {
    const std::size_t parent = std::uniform_int_distribution<std::size_t>(0, k - 1)(rng);
    const Vec3 step(normal(rng), 0.3 * normal(rng), 2.0 * normal(rng));
    u[k] = u[parent] + step;
    edges.push_back({parent, k, u[parent] - u[k]});
  }
  double brute = 0.0;
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) brute = std::max(brute, (u[a] - u[b]).norm());
  }
  const NetworkExtent e = measureNetworkExtent(n, edges, Vec3(0, 0, -1));
  EXPECT_NEAR(e.largestCentreDistance, brute, 1e-9);
  double zlo = 0, zhi = 0;
  for (const Vec3& x : u) {
    zlo = std::min(zlo, x.z());
    zhi = std::max(zhi, x.z());
  }
  EXPECT_NEAR(e.gravityExtent, zhi - zlo, 1e-9);
  EXPECT_NEAR(e.axisExtent.z(), zhi - zlo, 1e-9);
}

TEST(NetworkExtent, DisconnectedMembersAreAnError) {
  EXPECT_THROW(measureNetworkExtent(3, {{0, 1, Vec3(1, 0, 0)}}, Vec3::Zero()), Error);
}

TEST(ForceNetworks, BadContactListsAreErrorsNamingTheContact) {
  const auto message = [](const ParticleFrame& f) {
    try {
      analyzeForceNetworks(f);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  ParticleFrame base;
  addParticle(base, 1, Vec3(0, 0, 0), 0.5);
  addParticle(base, 2, Vec3(0.9, 0, 0), 0.5);

  ParticleFrame missing = base;
  addContact(missing, 1, 3, Vec3(-0.9, 0, 0), 1.0);
  EXPECT_NE(message(missing).find("particle id 3"), std::string::npos) << message(missing);

  ParticleFrame self = base;
  addContact(self, 2, 2, Vec3(-0.9, 0, 0), 1.0);
  EXPECT_NE(message(self).find("itself"), std::string::npos) << message(self);

  ParticleFrame twice = base;
  addContact(twice, 1, 2, Vec3(-0.9, 0, 0), 1.0);
  addContact(twice, 2, 1, Vec3(0.9, 0, 0), 1.0);
  EXPECT_NE(message(twice).find("more than once"), std::string::npos) << message(twice);

  ParticleFrame zero = base;
  addContact(zero, 1, 2, Vec3::Zero(), 1.0);
  EXPECT_NE(message(zero).find("branch"), std::string::npos) << message(zero);
}

}  // namespace
}  // namespace grainbridge::extract::structure
