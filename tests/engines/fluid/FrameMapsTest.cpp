// engines/fluid/FrameMaps: a field frame on the vertical plane and against height, for any
// gravity direction, with the depth averaged over.
#include "engines/fluid/FrameMaps.hpp"

#include <gtest/gtest.h>

#include "core/Error.hpp"

using namespace grainbridge;

namespace {

// A 3 x 4 x 2 grid, phase a's fraction 0.1 i + 0.01 j + 0.001 k, phase b's 0.5 where j == 0.
core::data::FieldFrame frame(const Vec3& gravity) {
  core::data::FieldFrame f;
  f.grid.cells = {3, 4, 2};
  f.grid.origin = Vec3(0.0, -1.0, 0.0);
  f.grid.spacing = Vec3(0.1, 0.2, 0.3);
  const std::size_t n = f.grid.cellCount();
  f.ep_g.assign(n, 0.0);
  f.p_g.assign(n, 0.0);
  f.u_g.assign(n, Vec3::Zero());
  for (const char* name : {"a", "b"}) {
    f.solids.push_back({name, std::vector<double>(n, 0.0), std::vector<Vec3>(n, Vec3::Zero()), std::vector<double>(n, 0.0)});
    f.materials.species.push_back({name, 1e-3, 2500.0});
  }
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 3; ++i) {
        f.solids[0].ep_s[f.grid.index(i, j, k)] = 0.1 * i + 0.01 * j + 0.001 * k;
        f.solids[1].ep_s[f.grid.index(i, j, k)] = j == 0 ? 0.5 : 0.0;
      }
  f.materials.gravity = gravity;
  return f;
}

}  // namespace

TEST(FrameMaps, TheMapSumsThePhasesAndAveragesTheDepth) {
  const fluid::PlaneMap map = fluid::solidsFractionMap(frame(Vec3(0.0, -9.81, 0.0)));
  ASSERT_EQ(map.columns, 3);
  ASSERT_EQ(map.rows, 4);
  EXPECT_DOUBLE_EQ(map.y0, -1.0);
  EXPECT_DOUBLE_EQ(map.dy, 0.2);
  ASSERT_EQ(map.values.size(), 12u);
  EXPECT_NEAR(map.values[0 * 3 + 2], 0.2 + 0.0005 + 0.5, 1e-15);  // row 0, column 2: both phases
  EXPECT_NEAR(map.values[3 * 3 + 1], 0.1 + 0.03 + 0.0005, 1e-15);
}

TEST(FrameMaps, TheProfileRunsFromTheBottomWhateverWayGravityPoints) {
  const auto up = fluid::solidsFractionProfile(frame(Vec3(0.0, -9.81, 0.0)), 0);
  const auto down = fluid::solidsFractionProfile(frame(Vec3(0.0, 9.81, 0.0)), 0);
  ASSERT_EQ(up.fraction.size(), 4u);
  EXPECT_DOUBLE_EQ(up.heights[0], 0.1);
  EXPECT_DOUBLE_EQ(up.heights[3], 0.7);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(up.fraction[k], 0.1 + 0.01 * static_cast<double>(k) + 0.0005, 1e-15);
    EXPECT_NEAR(down.fraction[k], up.fraction[3 - k], 1e-15);  // gravity up: row 3 is the bottom
  }
  EXPECT_NEAR(fluid::solidsFractionProfile(frame(Vec3(0.0, -9.81, 0.0)), 1).fraction[0], 0.5, 1e-15);
}

TEST(FrameMaps, AFrameWithoutMaterialsOrAPhaseOutOfRangeIsRefused) {
  core::data::FieldFrame f = frame(Vec3(0.0, -9.81, 0.0));
  EXPECT_THROW((void)fluid::solidsFractionProfile(f, 2), Error);
  f.materials = {};
  EXPECT_THROW((void)fluid::solidsFractionMap(f), Error);
}
