// Carnahan-Starling g0 (engines/closures/RadialDistribution.hpp): hand values, the MFIX
// three-term form, g0(0) = 1, monotonic growth, and refusal of solid fractions outside [0, 1).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/Error.hpp"
#include "engines/closures/RadialDistribution.hpp"

using grainbridge::Error;
using grainbridge::closures::carnahanStarlingG0;

namespace {

TEST(RadialDistribution, IsOneWithoutParticles) { EXPECT_DOUBLE_EQ(carnahanStarlingG0(0.0), 1.0); }

TEST(RadialDistribution, HandValues) {
  // (1 - eps/2) / (1 - eps)^3, evaluated by hand / python3:
  EXPECT_DOUBLE_EQ(carnahanStarlingG0(0.5), 6.0);                   // 0.75 / 0.125
  EXPECT_NEAR(carnahanStarlingG0(0.1), 1.3031550068587106, 1e-14);  // 0.95 / 0.729
  EXPECT_NEAR(carnahanStarlingG0(0.3), 2.478134110787172, 1e-14);   // 0.85 / 0.343
}

TEST(RadialDistribution, EqualsMfixThreeTermForm) {
  // MFIX G_0CS: 1/(1-eps) + 1.5 eps/(1-eps)^2 + 0.5 eps^2/(1-eps)^3, algebraically identical.
  for (double eps = 0.0; eps < 0.95; eps += 0.05) {
    const double v = 1.0 - eps;
    const double mfix = 1.0 / v + 1.5 * eps / (v * v) + 0.5 * eps * eps / (v * v * v);
    EXPECT_NEAR(carnahanStarlingG0(eps), mfix, 1e-12 * mfix) << "eps = " << eps;
  }
}

TEST(RadialDistribution, GrowsStrictlyWithSolidFraction) {
  double previous = carnahanStarlingG0(0.0);
  for (int i = 1; i < 100; ++i) {
    const double g = carnahanStarlingG0(0.01 * i);
    EXPECT_GT(g, previous) << "eps = " << 0.01 * i;
    previous = g;
  }
}

TEST(RadialDistribution, RefusesSolidFractionOutsideUnitInterval) {
  for (const double bad : {-0.01, 1.0, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
    try {
      (void)carnahanStarlingG0(bad);
      ADD_FAILURE() << "no error for eps = " << bad;
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("solid fraction must be in [0, 1)"));
    }
  }
  try {
    (void)carnahanStarlingG0(1.5);
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("got 1.5"));
  }
}

}  // namespace
