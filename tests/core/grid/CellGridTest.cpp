// CellGrid: C-order [k][j][i] indexing matching core's FieldFrame, the cell of a point with
// periodic and Lees-Edwards wrapping (exactly floor((x - lo) / spacing), faces included), and
// errors naming what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/Error.hpp"
#include "core/grid/CellGrid.hpp"
#include "core/grid/FastFloor.hpp"

using namespace grainbridge;
using namespace grainbridge::core::grid;

TEST(CellGrid, FlatIndexIsTheFieldFrameOrder) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(3, 4, 5), {3, 4, 5});
  const auto geometry = grid.geometry();
  EXPECT_EQ(grid.cellCount(), geometry.cellCount());
  for (int k = 0; k < 5; ++k) {
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 3; ++i) {
        const std::size_t flat = grid.flatIndex({i, j, k});
        EXPECT_EQ(flat, geometry.index(i, j, k));
        EXPECT_EQ(grid.cellIndex(flat), (CellIndex{i, j, k}));
      }
    }
  }
  EXPECT_EQ(geometry.origin, Vec3(0, 0, 0));
  EXPECT_EQ(geometry.spacing, Vec3(1, 1, 1));
}

TEST(CellGrid, CentreVolumeAndCellOfAPoint) {
  const CellGrid grid(Vec3(-1, 0, 2), Vec3(1, 3, 4), {4, 3, 1});
  EXPECT_DOUBLE_EQ(grid.cellVolume(), 0.5 * 1.0 * 2.0);
  EXPECT_TRUE(grid.cellCentre({1, 2, 0}).isApprox(Vec3(-0.25, 2.5, 3.0)));
  EXPECT_EQ(grid.cellOf(Vec3(-0.25, 2.5, 3.0)), (CellIndex{1, 2, 0}));
  // Half-open cells; the upper face of a non-periodic box belongs to the last cell.
  EXPECT_EQ(grid.cellOf(Vec3(0.0, 1.0, 2.0)), (CellIndex{2, 1, 0}));
  EXPECT_EQ(grid.cellOf(Vec3(1.0, 3.0, 4.0)), (CellIndex{3, 2, 0}));
  EXPECT_FALSE(grid.cellOf(Vec3(1.01, 1.0, 3.0)).has_value());
  EXPECT_FALSE(grid.cellOf(Vec3(0.0, -0.01, 3.0)).has_value());
}

TEST(CellGrid, PeriodicAxesWrap) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(4, 4, 4), {4, 4, 4}, {true, false, true});
  EXPECT_EQ(grid.cellOf(Vec3(-0.5, 1.5, 4.5)), (CellIndex{3, 1, 0}));
  EXPECT_EQ(grid.cellOf(Vec3(9.5, 1.5, -7.5)), (CellIndex{1, 1, 0}));
  EXPECT_FALSE(grid.cellOf(Vec3(1.5, 4.5, 1.5)).has_value());
}

TEST(CellGrid, LeesEdwardsImageAboveIsDisplacedByTheOffset) {
  // Domain.hpp: the image above the box in y is shifted by +offset in x, so a point just above
  // the top face is the image of the point one box lower and offset to the left.
  const CellGrid grid =
      CellGrid(Vec3(0, 0, 0), Vec3(10, 10, 1), {10, 10, 1}, {true, true, true}).withLeesEdwardsOffset(3.0);
  EXPECT_EQ(grid.cellOf(Vec3(5.5, 10.5, 0.5)), (CellIndex{2, 0, 0}));
  EXPECT_EQ(grid.cellOf(Vec3(5.5, -0.5, 0.5)), (CellIndex{8, 9, 0}));
  EXPECT_EQ(grid.cellOf(Vec3(1.5, 10.5, 0.5)), (CellIndex{8, 0, 0}));  // wraps in x as well
}

TEST(CellGrid, ImagesCoverAnObjectAcrossTheFaces) {
  const CellGrid grid =
      CellGrid(Vec3(0, 0, 0), Vec3(10, 10, 10), {5, 5, 5}, {true, true, false}).withLeesEdwardsOffset(2.5);
  std::vector<Vec3> shifts;
  grid.forEachImage(Vec3(-1, 9, 4), Vec3(1, 11, 6), [&](const Vec3& s) { shifts.push_back(s); });
  // y: images 0 and +1 (the latter displaced by -2.5 in x, so x spans [-3.5, -1.5]: one x image);
  // x for the y = 0 image spans [-1, 1]: two images. z is not periodic: one.
  ASSERT_EQ(shifts.size(), 3u);
  EXPECT_TRUE(shifts[0].isApprox(Vec3(10, 0, 0)));
  EXPECT_TRUE(shifts[1].isZero());
  EXPECT_TRUE(shifts[2].isApprox(Vec3(-2.5 + 10, -10, 0)));
}

TEST(CellGrid, ErrorsNameTheProblem) {
  try {
    CellGrid(Vec3(0, 0, 0), Vec3(1, 0, 1), {1, 1, 1});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("y range"), std::string::npos) << e.what();
  }
  try {
    CellGrid(Vec3(0, 0, 0), Vec3(1, 1, 1), {1, 1, 0});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("0 cells along z"), std::string::npos) << e.what();
  }
  EXPECT_THROW(CellGrid(Vec3(0, 0, 0), Vec3(1, 1, 1), {1, 1, 1}, {false, true, true}).withLeesEdwardsOffset(0.1),
               Error);
}

TEST(CellGrid, AxisCellIsTheFloorOfTheQuotientOnAndNextToFaces) {
  // Spacings that are not powers of two, so the quotient by multiplication and by division can
  // differ in the last bit.
  const CellGrid grid(Vec3(-0.3, 0.1, 2.0), Vec3(6.7, 4.3, 7.1), {7, 3, 11});
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> face(-20, 30);
  std::uniform_real_distribution<double> u(-20.0, 30.0);
  for (int trial = 0; trial < 20000; ++trial) {
    const int a = trial % 3;
    // Faces, a few ulps either side of them, and anywhere.
    double x = grid.lo()[a] + face(rng) * grid.spacing()[a];
    if (trial % 4 == 1) x = std::nextafter(x, -1e300);
    if (trial % 4 == 2) x = std::nextafter(std::nextafter(x, 1e300), 1e300);
    if (trial % 4 == 3) x = grid.lo()[a] + u(rng) * grid.spacing()[a];
    EXPECT_EQ(grid.axisCell(a, x), static_cast<int>(std::floor((x - grid.lo()[a]) / grid.spacing()[a]))) << x;
  }
}

TEST(FastFloor, MatchesStdFloor) {
  const double inf = std::numeric_limits<double>::infinity();
  for (const double x : {0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 2.999999999999999, -2.000000000000001, 1e15 + 0.5,
                         -1e15 - 0.5, 4503599627370497.0, -4503599627370497.0, 1e300, -1e300, inf, -inf}) {
    const double want = std::floor(x);
    EXPECT_EQ(floorExact(x), want) << x;
    EXPECT_EQ(std::signbit(floorExact(x)), std::signbit(want)) << x;
    if (std::abs(x) < 1e9) {
      EXPECT_EQ(floorToInt(x), static_cast<int>(want)) << x;
    }
  }
  EXPECT_TRUE(std::isnan(floorExact(std::numeric_limits<double>::quiet_NaN())));
}
