// Eq. 3.60 with the superbee limiter: second order on smooth profiles, upwind at extrema, and a
// face value that never leaves the range of its two cells (TVD).
#include "engines/fluid/Superbee.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace grainbridge::fluid {
namespace {

TEST(Superbee, LimiterFollowsItsPiecewiseDefinition) {
  EXPECT_EQ(superbeeLimiter(-1.0), 0.0);
  EXPECT_EQ(superbeeLimiter(0.0), 0.0);
  EXPECT_DOUBLE_EQ(superbeeLimiter(0.25), 0.5);  // 2r
  EXPECT_DOUBLE_EQ(superbeeLimiter(0.75), 1.0);  // 1
  EXPECT_DOUBLE_EQ(superbeeLimiter(1.5), 1.5);   // r
  EXPECT_DOUBLE_EQ(superbeeLimiter(5.0), 2.0);   // 2
  // Symmetric: psi(r) / r = psi(1 / r), so forward and backward gradients are treated alike.
  for (double r : {0.1, 0.4, 0.8, 1.3, 2.5, 7.0}) EXPECT_NEAR(superbeeLimiter(r) / r, superbeeLimiter(1.0 / r), 1e-15);
}

TEST(Superbee, LinearProfileGivesTheCentralFaceValueInBothDirections) {
  // Phi = 2 + 3x at x = 0, 1, 2, 3: the face between 1 and 2 carries 6.5 exactly.
  EXPECT_DOUBLE_EQ(superbeeFaceValue(+1.0, 2.0, 5.0, 8.0, 11.0), 6.5);
  EXPECT_DOUBLE_EQ(superbeeFaceValue(-1.0, 2.0, 5.0, 8.0, 11.0), 6.5);
}

TEST(Superbee, ExtremumGivesTheUpwindValue) {
  EXPECT_DOUBLE_EQ(superbeeFaceValue(+1.0, 4.0, 5.0, 1.0, 0.0), 5.0);  // P is a maximum
  EXPECT_DOUBLE_EQ(superbeeFaceValue(-1.0, 0.0, 1.0, 5.0, 4.0), 5.0);  // E is a maximum
  EXPECT_DOUBLE_EQ(superbeeFaceValue(+1.0, 1.0, 3.0, 3.0, 7.0), 3.0);  // no gradient across the face
}

TEST(Superbee, FaceValueStaysBetweenItsTwoCells) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(-10.0, 10.0);
  for (int n = 0; n < 10000; ++n) {
    const double w = value(rng), p = value(rng), e = value(rng), ee = value(rng);
    for (double u : {-1.0, 1.0}) {
      const double f = superbeeFaceValue(u, w, p, e, ee);
      EXPECT_GE(f, std::min(p, e) - 1e-12);
      EXPECT_LE(f, std::max(p, e) + 1e-12);
    }
  }
}

}  // namespace
}  // namespace grainbridge::fluid
