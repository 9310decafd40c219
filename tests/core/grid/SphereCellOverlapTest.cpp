// Exact sphere-cell overlap shares: they sum to the whole sphere (1e-12 relative) wherever the
// sphere sits in a periodic box, including across a Lees-Edwards boundary; a sphere inside one
// cell goes whole to it; a non-periodic face drops what lies beyond (the cap formula).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "core/grid/SphereCellOverlap.hpp"

using namespace grainbridge;
using namespace grainbridge::core::grid;

namespace {
double total(const CellShares& shares) {
  double s = 0.0;
  for (const auto& x : shares) s += x.fraction;
  return s;
}
}  // namespace

TEST(SphereCellOverlap, SharesSumToTheWholeSphereInAPeriodicBox) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const CellGrid plain(Vec3(0, 0, 0), Vec3(4, 3, 5), {5, 4, 6}, {true, true, true});
  const CellGrid sheared = plain.withLeesEdwardsOffset(1.37);
  CellShares shares;
  for (const CellGrid* grid : {&plain, &sheared}) {
    for (int trial = 0; trial < 200; ++trial) {
      const Vec3 c(4 * u(rng), 3 * u(rng), 5 * u(rng));
      const double r = 0.1 + 1.2 * u(rng);  // up to about two cells across
      sphereCellShares(*grid, c, r, shares);
      EXPECT_NEAR(total(shares), 1.0, 1e-12) << "centre " << c.transpose() << " r " << r;
    }
  }
}

TEST(SphereCellOverlap, LeesEdwardsPutsTheCrossingPartInTheDisplacedCells) {
  // A sphere poking out of the top face: its top cap re-enters at the bottom, displaced by -offset
  // in x. With cells of width 1 and offset 2.5 the cap is centred at x = 5.5 - 2.5 = 3.0 and
  // straddles cells 2 and 3 of the bottom row equally.
  const CellGrid grid =
      CellGrid(Vec3(0, 0, 0), Vec3(10, 10, 1), {10, 10, 1}, {true, true, true}).withLeesEdwardsOffset(2.5);
  CellShares shares;
  const double r = 0.4, t = 0.3;  // plane y = 10 is t below the top of... centre at y = 10 - t
  sphereCellShares(grid, Vec3(5.5, 10.0 - t, 0.5), r, shares);
  std::map<std::size_t, double> byCell;
  for (const auto& s : shares) byCell[s.cell] += s.fraction;
  const double capFraction = M_PI * (r - t) * (r - t) * (2 * r + t) / 3.0 / (4.0 / 3.0 * M_PI * r * r * r);
  EXPECT_NEAR(byCell[grid.flatIndex({2, 0, 0})], 0.5 * capFraction, 1e-14);
  EXPECT_NEAR(byCell[grid.flatIndex({3, 0, 0})], 0.5 * capFraction, 1e-14);
  EXPECT_NEAR(byCell[grid.flatIndex({5, 9, 0})], 1.0 - capFraction, 1e-14);
}

TEST(SphereCellOverlap, SphereInsideOneCellGoesWholeToIt) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(3, 3, 3), {3, 3, 3});
  CellShares shares;
  sphereCellShares(grid, Vec3(1.5, 0.5, 2.45), 0.5 - 0.051, shares);
  ASSERT_EQ(shares.size(), 1u);
  EXPECT_EQ(shares[0].cell, grid.flatIndex({1, 0, 2}));
  EXPECT_EQ(shares[0].fraction, 1.0);
}

TEST(SphereCellOverlap, NonPeriodicFaceDropsTheCapBeyondIt) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(2, 2, 2), {2, 2, 2});
  CellShares shares;
  const double r = 0.5, t = 0.2;  // centre 0.2 inside the face x = 0
  sphereCellShares(grid, Vec3(t, 1.0, 1.0), r, shares);
  const double capFraction = M_PI * (r - t) * (r - t) * (2 * r + t) / 3.0 / (4.0 / 3.0 * M_PI * r * r * r);
  EXPECT_NEAR(total(shares), 1.0 - capFraction, 1e-14);
}
