// MFiX's algebraic granular temperature (gt_algebraic, engines/mfm/MultiFluidModel.hpp) as the
// solids vanish: theta = -c / (K4 eps) grows as 1/eps, stays finite wherever eps > 1e-15, and is
// zero at and below it (MFiX's SMALL_NUMBER), where it once overflowed to infinity (5e-316 of
// chaff in the combine, issue 56) and the pressure slope 2 K1 eps theta with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engines/closures/SyamlalAlgebraic.hpp"
#include "engines/mfm/MultiFluidModel.hpp"

using namespace grainbridge;

TEST(AlgebraicTemperature, GrowsAsOneOverEpsAndIsZeroWithoutSolids) {
  const closures::SyamlalAlgebraic model;
  const double traceD = 0.0, doubleDotD = 2.0 * 50.0 * 50.0;  // simple shear at 100 1/s
  auto theta = [&](double eps) {
    const closures::KineticState s{std::max(eps, 0.0), 0.0, 2.3e-3, 40.6, 0.9, 0.0};
    return mfm::algebraicGranularTemperature(model.coefficients(s), eps, traceD, doubleDotD);
  };
  // The dilute limit: K1..K4 tend to constants, so eps theta tends to one too.
  EXPECT_NEAR(1e-10 * theta(1e-10), 1e-12 * theta(1e-12), 1e-6 * 1e-10 * theta(1e-10));
  for (const double eps : {1e-14, 2e-15}) {
    EXPECT_TRUE(std::isfinite(theta(eps))) << eps;
    EXPECT_TRUE(std::isfinite(2.0 * eps * theta(eps))) << eps;
  }
  for (const double eps : {1e-15, 1e-200, 5.2e-316, 0.0, -1e-20}) EXPECT_EQ(theta(eps), 0.0) << eps;
}
