// The bed measures (engines/fluid/BedMeasures) on a small column whose answers are known by hand:
// heights grow against gravity whichever axis and sign it has, Eq. 5.22's mean height is the
// centroid of the solids, the pressure between cell centres is linear, and the solids volume is
// the sum of eps_s times the cell volume.
#include "engines/fluid/BedMeasures.hpp"

#include <gtest/gtest.h>

#include "core/Error.hpp"

namespace grainbridge::fluid {
namespace {

// 2 x 4 cells of 0.1 m x 0.25 m, 0.5 m deep; gas plus one solids phase.
core::data::GridGeometry column() {
  core::data::GridGeometry g;
  g.spacing = Vec3(0.1, 0.25, 0.5);
  g.cells = {2, 4, 1};
  return g;
}

TEST(BedMeasures, VerticalAxisPointsAgainstGravity) {
  EXPECT_EQ(verticalAxis(Vec3(0.0, -9.81, 0.0)).axis, 1);
  EXPECT_EQ(verticalAxis(Vec3(0.0, -9.81, 0.0)).up, 1.0);
  EXPECT_EQ(verticalAxis(Vec3(0.0, 0.0, 9.81)).axis, 2);
  EXPECT_EQ(verticalAxis(Vec3(0.0, 0.0, 9.81)).up, -1.0);
}

TEST(BedMeasures, MeanHeightPressureAndVolumeOfAColumn) {
  const StaggeredGrid grid(column());
  FlowState st(grid, 2);
  // Solids in the two lowest rows: 0.6 in row 0, 0.2 in row 1; pressure falls 100 Pa per row.
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 4; ++j) {
      st.phases[1].fraction(i, j, 0) = j == 0 ? 0.6 : (j == 1 ? 0.2 : 0.0);
      st.pressure(i, j, 0) = 1000.0 - 100.0 * j;
    }
  }
  const VerticalAxis up = verticalAxis(Vec3(0.0, -9.81, 0.0));
  // Row centres at 0.125 and 0.375 m, weighted 3 : 1.
  EXPECT_DOUBLE_EQ(meanParticleHeight(st, up, 1), (0.6 * 0.125 + 0.2 * 0.375) / 0.8);
  EXPECT_DOUBLE_EQ(meanParticleHeight(st, up, 0), 0.0);  // the gas holds no fraction here
  EXPECT_DOUBLE_EQ(pressureAtHeight(st, up, 0.25), 950.0);
  EXPECT_DOUBLE_EQ(pressureAtHeight(st, up, 0.0), 1050.0);  // extrapolated to the inlet face
  EXPECT_DOUBLE_EQ(solidsVolume(st, 1), 2 * (0.6 + 0.2) * 0.1 * 0.25 * 0.5);
  // Gravity along +y: the same column read upside down.
  const VerticalAxis down = verticalAxis(Vec3(0.0, 9.81, 0.0));
  EXPECT_DOUBLE_EQ(meanParticleHeight(st, down, 1), (0.6 * 0.875 + 0.2 * 0.625) / 0.8);
}

// A mixture's Eq. 5.22 height is that of all its solids: the same column with its two rows
// held by two phases gives the one-phase column's height.
TEST(BedMeasures, MixtureMeanHeightIsEq522OverAllSolids) {
  const StaggeredGrid grid(column());
  FlowState st(grid, 3);
  for (int i = 0; i < 2; ++i) {
    st.phases[1].fraction(i, 0, 0) = 0.6;  // the lower row: phase 1
    st.phases[2].fraction(i, 1, 0) = 0.2;  // the upper row: phase 2
  }
  const VerticalAxis up = verticalAxis(Vec3(0.0, -9.81, 0.0));
  const std::vector<double> heights{meanParticleHeight(st, up, 1), meanParticleHeight(st, up, 2)};
  const std::vector<double> volumes{solidsVolume(st, 1), solidsVolume(st, 2)};
  EXPECT_DOUBLE_EQ(heights[0], 0.125);
  EXPECT_DOUBLE_EQ(heights[1], 0.375);
  EXPECT_DOUBLE_EQ(mixtureMeanHeight(heights, volumes), (0.6 * 0.125 + 0.2 * 0.375) / 0.8);
  EXPECT_DOUBLE_EQ(mixtureMeanHeight({0.1}, {0.0}), 0.0);  // no solids
}

}  // namespace
}  // namespace grainbridge::fluid

namespace grainbridge::fluid {
namespace {

// Eqs. 5.23-5.25 on beds whose heights are known by hand: the mixed start of a binary bed (both
// phases everywhere in the bed) gives s_p = 0; the same inventory fully separated, the large
// particles below the small with their interface on a cell face, gives s_p = 100 %, at equal and
// at unequal shares x_small.
TEST(BedMeasures, SegregationPercentageIsZeroMixedAndOneHundredSeparated) {
  const core::data::GridGeometry geometry = [] {
    core::data::GridGeometry g;
    g.spacing = Vec3(0.01, 0.01, 0.015);
    g.cells = {3, 12, 1};
    return g;
  }();
  const StaggeredGrid grid(geometry);
  const VerticalAxis up = verticalAxis(Vec3(0.0, -9.81, 0.0));
  for (const int smallRows : {4, 2}) {  // x_small 1/2 and 1/4 of an 8-row bed
    const int rows = 8;
    const double x = static_cast<double>(smallRows) / rows;
    FlowState mixed(grid, 3), separated(grid, 3);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < rows; ++j) {
        mixed.phases[1].fraction(i, j, 0) = 0.583 * x;
        mixed.phases[2].fraction(i, j, 0) = 0.583 * (1.0 - x);
        (j < rows - smallRows ? separated.phases[2] : separated.phases[1]).fraction(i, j, 0) = 0.583;
      }
    }
    EXPECT_NEAR(solidsVolume(separated, 1), solidsVolume(mixed, 1), 1e-15);
    EXPECT_NEAR(segregationPercentage(meanParticleHeight(mixed, up, 1), meanParticleHeight(mixed, up, 2), x), 0.0,
                1e-12)
        << "x_small " << x;
    EXPECT_NEAR(segregationPercentage(meanParticleHeight(separated, up, 1), meanParticleHeight(separated, up, 2), x),
                100.0, 1e-10)
        << "x_small " << x;
  }
  EXPECT_THROW((void)segregationPercentage(0.1, 0.1, 1.0), Error);
  EXPECT_THROW((void)segregationPercentage(0.1, 0.0, 0.5), Error);
}

}  // namespace
}  // namespace grainbridge::fluid
