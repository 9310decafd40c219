// The force loop's inner list (NeighborList::buildInner): the listed pairs within
// a_i + a_j + inner skin, in the list's order, with the history of every pair left out cleared;
// and, in a run, no touching pair ever left out of it.
#include <gtest/gtest.h>

#include <cmath>

#include "engines/dem/NeighborList.hpp"
#include "tests/engines/dem/DemTestSupport.hpp"

namespace grainbridge::dem {
namespace {

using testing::periodicGas;
using testing::table61Particle;

TEST(InnerList, HoldsTheListedPairsWithinItsReachInOrderAndClearsTheOthersHistory) {
  // A dense gas in an open box (no ghosts): about half its listed pairs lie beyond the inner reach.
  auto gas = periodicGas(300, 0.35, 1.0, table61Particle(), 2e-4, 7);
  const Particles& p = gas.particles;
  const double skin = 0.3;
  const double innerSkin = 0.075;
  NeighborList list;
  list.build(p, gas.setup.lo, gas.setup.hi, 1.0 + skin, skin);
  for (std::size_t s = 0; s < list.pairCount(); ++s) list.history(s) = Vec3(1.0, -2.0, 3.0);
  list.buildInner(p, innerSkin);

  std::vector<bool> inner(list.pairCount(), false);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    std::size_t lastSlot = 0;
    for (std::size_t k = list.innerBegin(i); k < list.innerEnd(i); ++k) {
      const std::size_t s = list.innerSlot(k);
      ASSERT_GE(s, list.begin(i));
      ASSERT_LT(s, list.end(i));
      if (k > list.innerBegin(i)) {
        ASSERT_GT(s, lastSlot) << "the list's order";
      }
      lastSlot = s;
      ASSERT_EQ(list.innerPartner(k), list.partner(s));
      inner[s] = true;
      ++kept;
    }
    for (std::size_t s = list.begin(i); s < list.end(i); ++s) {
      const std::size_t j = list.partner(s);
      const double reach = p.radius[i] + p.radius[j] + innerSkin;
      const bool within = (p.x[i] - p.x[j]).squaredNorm() < reach * reach;
      EXPECT_EQ(inner[s], within) << "pair " << i << "-" << j;
      if (within) {
        EXPECT_EQ(list.history(s), Vec3(1.0, -2.0, 3.0)) << "a kept pair keeps its history";
      } else {
        EXPECT_TRUE(list.history(s).isZero(0.0)) << "a pair left out is apart: its history is cleared";
      }
    }
  }
  EXPECT_EQ(kept, list.innerPairCount());
  EXPECT_GT(kept, 0U);
  EXPECT_LT(kept, list.pairCount()) << "the inner list should be shorter in this gas";
}

// Touching pairs of a periodic cubic box by brute force over minimum images.
std::size_t touchingPairs(const Particles& p, double side) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    for (std::size_t j = i + 1; j < p.nOwned; ++j) {
      Vec3 r = p.x[i] - p.x[j];
      for (int a = 0; a < 3; ++a) r[a] -= side * std::round(r[a] / side);
      const double reach = p.radius[i] + p.radius[j];
      if (r.squaredNorm() < reach * reach) ++n;
    }
  }
  return n;
}

TEST(InnerList, LeavesOutNoTouchingPairWhileParticlesMove) {
  // A hot, fairly dense gas: the inner list (a quarter of the skin) is rebuilt many times, the
  // Verlet list a few; at every step the contacts the force loop finds are all there are.
  auto gas = periodicGas(250, 0.3, 20.0, table61Particle(), 2e-4, 11);
  Simulation sim(gas.setup, gas.particles);
  for (int step = 0; step < 1500; ++step) {
    sim.step(/*recordContacts=*/true);
    ASSERT_EQ(sim.frame().contacts.size(), touchingPairs(sim.particles(), gas.side)) << "step " << step;
  }
  EXPECT_GT(sim.innerRebuilds(), 3 * sim.rebuilds()) << "the inner list was rebuilt between Verlet builds";
}

}  // namespace
}  // namespace grainbridge::dem
