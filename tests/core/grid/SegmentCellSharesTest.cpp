// Exact clipping of a segment at cell faces: the fractions are the lengths in each cell, they
// sum to 1 in a periodic box (also across a Lees-Edwards boundary), and a non-periodic face
// drops the length beyond it.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "core/grid/SegmentCellShares.hpp"

using namespace grainbridge;
using namespace grainbridge::core::grid;

namespace {
std::map<std::size_t, double> byCell(const CellShares& shares) {
  std::map<std::size_t, double> m;
  for (const auto& s : shares) m[s.cell] += s.fraction;
  return m;
}
}  // namespace

TEST(SegmentCellShares, FractionsAreTheLengthsInEachCell) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(4, 4, 1), {4, 4, 1});
  CellShares shares;
  // From (0.5, 0.5) to (2.5, 1.5): crosses x = 1, x = 2 and y = 1 at s = 0.25, 0.75 and 0.5.
  segmentCellShares(grid, Vec3(0.5, 0.5, 0.5), Vec3(2.5, 1.5, 0.5), shares);
  auto m = byCell(shares);
  ASSERT_EQ(m.size(), 4u);
  EXPECT_NEAR(m[grid.flatIndex({0, 0, 0})], 0.25, 1e-15);
  EXPECT_NEAR(m[grid.flatIndex({1, 0, 0})], 0.25, 1e-15);
  EXPECT_NEAR(m[grid.flatIndex({1, 1, 0})], 0.25, 1e-15);
  EXPECT_NEAR(m[grid.flatIndex({2, 1, 0})], 0.25, 1e-15);
}

TEST(SegmentCellShares, SumToOneInAPeriodicBoxAndAcrossTheShearingBoundary) {
  const CellGrid plain(Vec3(0, 0, 0), Vec3(3, 3, 3), {5, 4, 3}, {true, true, true});
  const CellGrid sheared = plain.withLeesEdwardsOffset(1.1);
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  CellShares shares;
  for (const CellGrid* grid : {&plain, &sheared}) {
    for (int trial = 0; trial < 200; ++trial) {
      const Vec3 a(3 * u(rng), 3 * u(rng), 3 * u(rng));
      const Vec3 b = a + 2.0 * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
      segmentCellShares(*grid, a, b, shares);
      double sum = 0.0;
      for (const auto& s : shares) sum += s.fraction;
      EXPECT_NEAR(sum, 1.0, 1e-14);
    }
  }
  // A vertical segment through the top face re-enters displaced by -offset in x.
  segmentCellShares(sheared, Vec3(1.5, 2.6, 0.5), Vec3(1.5, 3.4, 0.5), shares);
  auto m = byCell(shares);
  const int iAbove = sheared.axisCell(0, 1.5 - 1.1);
  EXPECT_NEAR(m[sheared.flatIndex({2, 3, 0})], 0.5, 1e-14);
  EXPECT_NEAR(m[sheared.flatIndex({iAbove, 0, 0})], 0.5, 1e-14);
}

TEST(SegmentCellShares, NonPeriodicFaceDropsTheLengthBeyond) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(2, 2, 2), {2, 2, 2});
  CellShares shares;
  segmentCellShares(grid, Vec3(0.3, 1.0, 1.0), Vec3(-0.7, 1.0, 1.0), shares);
  double sum = 0.0;
  for (const auto& s : shares) sum += s.fraction;
  EXPECT_NEAR(sum, 0.3, 1e-15);
}
