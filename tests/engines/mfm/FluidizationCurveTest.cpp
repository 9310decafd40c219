// Reading Fig. 4.5's curves: an Ergun-shaped packed branch meeting a plateau gives back the
// plateau and the velocity where they meet, whatever noise the plateau points carry.
#include <gtest/gtest.h>

#include "engines/mfm/FluidizationCurve.hpp"

using namespace grainbridge::mfm;

TEST(FluidizationCurve, FindsThePlateauAndWhereThePackedBranchMeetsIt) {
  // dp = 500 U + 300 U^2 meets 664 Pa at U = 0.8719 m/s.
  std::vector<CurvePoint> points;
  for (int n = 1; n <= 10; ++n) {
    const double u = 0.1035 * n;
    const double packed = 500.0 * u + 300.0 * u * u;
    points.push_back({u, packed < 664.0 ? packed : 664.0 + (n % 2 ? 5.0 : -5.0), 3.0});
  }
  const auto r = readFluidizationCurve(points);
  ASSERT_TRUE(r.found);
  EXPECT_NEAR(r.plateau, 664.0, 2.0);
  EXPECT_NEAR(r.fluidizationVelocity, 0.8719, 0.005);
  EXPECT_EQ(r.plateauPoints, 2);  // 0.9315 and 1.035 m/s
}

TEST(FluidizationCurve, ACurveThatNeverLevelsOffHasNoReading) {
  std::vector<CurvePoint> points;
  for (int n = 1; n <= 5; ++n) points.push_back({0.1 * n, 100.0 * n, 1.0});
  EXPECT_FALSE(readFluidizationCurve(points).found);
}
