// The particle-bed measures of the TF-DEM reports: the arithmetic mean height along gravity (line
// 1982) and the contact numbers of Figs. 7.5 and 7.11.
#include <gtest/gtest.h>

#include <vector>

#include "engines/tfdem/ParticleBedMeasures.hpp"

namespace grainbridge::tfdem {
namespace {

TEST(ParticleBedMeasures, MeanHeightIsMeasuredAgainstGravityFromTheBottom) {
  const std::vector<Vec3> x{{0.0, 0.1, 0.0}, {0.0, 0.3, 0.0}};
  EXPECT_DOUBLE_EQ(meanParticleHeight(x, fluid::VerticalAxis{1, 1.0}, 0.0), 0.2);
  // Gravity along +y: the bottom is the top side at y = 0.5.
  EXPECT_DOUBLE_EQ(meanParticleHeight(x, fluid::VerticalAxis{1, -1.0}, 0.5), 0.3);
  EXPECT_EQ(meanParticleHeight(std::vector<Vec3>{}, fluid::VerticalAxis{1, 1.0}, 0.0), 0.0);
}

TEST(ParticleBedMeasures, ContactNumbersCountNeighboursPerParticle) {
  // A chain 0-1-2 and a pair 3-4 among 6 particles (5 touches nothing): 3 contacts, so the
  // coordination is 6/6; N_c is 1, 2, 1, 1, 1 for the five touching, one of them multi.
  core::data::ContactList c;
  c.i = {0, 1, 3};
  c.j = {1, 2, 4};
  const ContactNumbers n = contactNumbers(c, 6);
  EXPECT_DOUBLE_EQ(n.coordination, 1.0);
  EXPECT_DOUBLE_EQ(n.multiContactRatio, 1.0 / 5.0);
  // A triangle: everyone has two neighbours.
  c.i = {0, 1, 2};
  c.j = {1, 2, 0};
  EXPECT_DOUBLE_EQ(contactNumbers(c, 3).multiContactRatio, 1.0);
  EXPECT_DOUBLE_EQ(contactNumbers(core::data::ContactList{}, 3).multiContactRatio, 0.0);
}

}  // namespace
}  // namespace grainbridge::tfdem
