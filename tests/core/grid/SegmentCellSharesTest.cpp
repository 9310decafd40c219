// Exact clipping of a segment at cell faces: the fractions are the lengths in each cell, they
// sum to 1 in a periodic box (also across a Lees-Edwards boundary), and a non-periodic face
// drops the length beyond it. The walk gives exactly the cells and fractions of sorting every
// face crossing, long segments and segments along faces and through edges included.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <vector>

#include "core/grid/SegmentCellShares.hpp"

using namespace grainbridge;
using namespace grainbridge::core::grid;

namespace {
std::map<std::size_t, double> byCell(const CellShares& shares) {
  std::map<std::size_t, double> m;
  for (const auto& s : shares) m[s.cell] += s.fraction;
  return m;
}

// Clipping by sorting: all face crossings of each image in one sorted list, each piece to the
// cell of its midpoint (what the walk replaced).
CellShares sortedCrossingShares(const CellGrid& grid, const Vec3& start, const Vec3& end) {
  CellShares out;
  const Vec3 d = end - start;
  if (d.squaredNorm() == 0.0) {
    if (const auto cell = grid.cellOf(start)) out.push_back({grid.flatIndex(*cell), 1.0});
    return out;
  }
  grid.forEachImage(start.cwiseMin(end), start.cwiseMax(end), [&](const Vec3& shift) {
    const Vec3 p = start + shift;
    std::vector<double> cuts{0.0, 1.0};
    for (int a = 0; a < 3; ++a) {
      if (d[a] == 0.0) continue;
      const int c0 = static_cast<int>(std::floor((p[a] - grid.lo()[a]) / grid.spacing()[a]));
      const int c1 = static_cast<int>(std::floor((p[a] + d[a] - grid.lo()[a]) / grid.spacing()[a]));
      for (int f = std::min(c0, c1) + 1; f <= std::max(c0, c1); ++f) {
        const double s = (grid.lo()[a] + f * grid.spacing()[a] - p[a]) / d[a];
        if (s > 0.0 && s < 1.0) cuts.push_back(s);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t n = 0; n + 1 < cuts.size(); ++n) {
      const double ds = cuts[n + 1] - cuts[n];
      if (ds <= 0.0) continue;
      const Vec3 mid = p + 0.5 * (cuts[n] + cuts[n + 1]) * d;
      const CellIndex cell{static_cast<int>(std::floor((mid[0] - grid.lo()[0]) / grid.spacing()[0])),
                           static_cast<int>(std::floor((mid[1] - grid.lo()[1]) / grid.spacing()[1])),
                           static_cast<int>(std::floor((mid[2] - grid.lo()[2]) / grid.spacing()[2]))};
      if (grid.contains(cell)) out.push_back({grid.flatIndex(cell), ds});
    }
  });
  return out;
}

void expectSameShares(const CellShares& got, const CellShares& want, const Vec3& a, const Vec3& b) {
  ASSERT_EQ(got.size(), want.size()) << "segment " << a.transpose() << " -> " << b.transpose();
  for (std::size_t n = 0; n < got.size(); ++n) {
    EXPECT_EQ(got[n].cell, want[n].cell) << "piece " << n << " of " << a.transpose() << " -> " << b.transpose();
    EXPECT_EQ(got[n].fraction, want[n].fraction) << "piece " << n << " of " << a.transpose() << " -> " << b.transpose();
  }
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

TEST(SegmentCellShares, TheWalkGivesTheCellsAndFractionsOfSortingEveryCrossing) {
  const CellGrid periodic(Vec3(-1, 0, 2), Vec3(5, 4.5, 7), {7, 5, 6}, {true, true, false});
  const CellGrid sheared = periodic.withLeesEdwardsOffset(2.7);
  const CellGrid region(Vec3(0.5, 0.5, 2.5), Vec3(4, 4, 6), {5, 4, 3});
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  CellShares shares;
  for (const CellGrid* grid : {&periodic, &sheared, &region}) {
    const Vec3 lo = grid->lo() - Vec3::Constant(1.0), size = grid->length() + Vec3::Constant(2.0);
    // Contact lines (about a cell long) and segments across many cells.
    for (const double reach : {1.0, 3.0, 9.0}) {
      for (int trial = 0; trial < 400; ++trial) {
        const Vec3 a = lo + size.cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
        const Vec3 b = a + reach * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
        segmentCellShares(*grid, a, b, shares);
        expectSameShares(shares, sortedCrossingShares(*grid, a, b), a, b);
      }
    }
  }
}

TEST(SegmentCellShares, SegmentsAlongFacesAndThroughEdgesAndCorners) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(4, 4, 4), {4, 4, 4}, {true, true, false});
  CellShares shares;
  const std::vector<std::pair<Vec3, Vec3>> segments{
      {Vec3(1, 1, 1), Vec3(3, 3, 3)},                // through cell corners
      {Vec3(0.5, 1, 1), Vec3(2.5, 3, 1)},            // in the face z = 1, through edges
      {Vec3(1, 1, 0.5), Vec3(1, 3.5, 0.5)},          // along an edge
      {Vec3(2, 2, 2), Vec3(2, 2, 2)},                // a point on a corner
      {Vec3(3.5, 3.5, 1.5), Vec3(4.5, 4.5, 1.5)},    // through the periodic corner
      {Vec3(0, 0, 0), Vec3(-1, -1, 1)},              // from the box corner out through both images
      {Vec3(1.25, 0.5, 3.5), Vec3(1.25, 0.5, 4.5)},  // through the top face: the rest is dropped
  };
  for (const auto& [a, b] : segments) {
    for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
      segmentCellShares(grid, from, to, shares);
      expectSameShares(shares, sortedCrossingShares(grid, from, to), from, to);
    }
  }
  // Through corners: a third of the length in each cell on the diagonal, none beside it.
  segmentCellShares(grid, Vec3(1, 1, 1), Vec3(3, 3, 3), shares);
  auto m = byCell(shares);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[grid.flatIndex({1, 1, 1})], 0.5);
  EXPECT_EQ(m[grid.flatIndex({2, 2, 2})], 0.5);
}
