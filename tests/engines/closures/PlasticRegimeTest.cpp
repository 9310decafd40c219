// The plastic regime (engines/closures/PlasticRegime: Eqs. 3.26-3.27, Schaeffer's viscosity as
// MFIX writes it): P* in SI, the switch at eps_g*, the viscosity and its cap, and the degree /
// radian trap.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "core/units/Quantity.hpp"
#include "engines/closures/PlasticRegime.hpp"

using namespace grainbridge;
using namespace grainbridge::closures;

namespace {

PlasticRegime goldschmidt() {
  PlasticRegime p;
  p.params.criticalVoidFraction = 0.417;  // eps_mf of the Goldschmidt bed
  return p;
}

TEST(PlasticRegime, PStarIsTheCgsLawInPascal) {
  // A = 1e25 dyn/cm^2 (the reference, cgs) = 1e24 Pa; at eps_g = eps_g* - 0.01: 1e24 x 1e-20.
  const auto r = goldschmidt().evaluate(0.407, 0.593, 1.0);
  EXPECT_TRUE(r.plastic);
  EXPECT_NEAR(r.pStar, 1.0e4, 1e-6);
  EXPECT_NEAR(r.pressure, 0.593 * 1.0e4, 1e-6);  // Eq. 3.26
  // The cgs coefficient converted by the unit system gives the same A.
  const auto a =
      core::units::parseQuantity("1e25 dyne/cm2", core::units::Dimension::pressure(), core::units::UnitSystem::si());
  EXPECT_NEAR(std::get<double>(a), PlasticRegime::Params{}.coefficient, 1e10);
}

TEST(PlasticRegime, VanishesAtAndAboveTheCriticalVoidFraction) {
  for (const double epsG : {0.417, 0.5, 1.0}) {
    const auto r = goldschmidt().evaluate(epsG, 1.0 - epsG, 4.0);
    EXPECT_FALSE(r.plastic);
    EXPECT_EQ(r.pressure, 0.0);
    EXPECT_EQ(r.viscosity, 0.0);
  }
  // Continuous into the switch: P* -> 0 as eps_g -> eps_g*.
  EXPECT_LT(goldschmidt().evaluate(0.417 - 1e-3, 0.583, 1.0).pStar, 1e-5);
}

TEST(PlasticRegime, SchaefferViscosityAndItsCap) {
  // P* = 1e4 Pa, phi = 30 degrees, I2D = 1e6 1/s^2: mu = 1e4 x 0.5 / (2 x 1e3) = 2.5 Pa s.
  EXPECT_NEAR(goldschmidt().evaluate(0.407, 0.593, 1.0e6).viscosity, 2.5, 1e-12);
  // Slow shear: capped at 100 Pa s (MFIX's 1000 poise), and at zero strain rate too.
  EXPECT_EQ(goldschmidt().evaluate(0.407, 0.593, 1.0).viscosity, 100.0);
  EXPECT_EQ(goldschmidt().evaluate(0.407, 0.593, 0.0).viscosity, 100.0);
}

TEST(PlasticRegime, AnglesAreRadiansInsideAndDegreesAreRefusedAsBareNumbers) {
  // A config says "30 degree": the unit system makes it pi/6, which is the default.
  const auto thirty =
      core::units::parseQuantity("30 degree", core::units::Dimension::none(), core::units::UnitSystem::si());
  EXPECT_NEAR(std::get<double>(thirty), PlasticRegime::Params{}.internalFrictionAngle, 1e-15);
  // A bare 30 is 30 rad: refused with the fix, never used as sin(30 rad) = -0.988.
  PlasticRegime p = goldschmidt();
  p.params.internalFrictionAngle = 30.0;
  EXPECT_THAT(p.params.problem(), ::testing::HasSubstr("write \"30 degree\" for degrees"));
  EXPECT_THROW((void)p.evaluate(0.407, 0.593, 1.0), Error);
  p.params.internalFrictionAngle = 0.0;
  EXPECT_THAT(p.params.problem(), ::testing::HasSubstr("angle of internal friction must be in (0, 90) degrees"));
}

TEST(PlasticRegime, NeedsItsCriticalVoidFraction) {
  EXPECT_THAT(PlasticRegime{}.params.problem(), ::testing::HasSubstr("critical void fraction eps_g*"));
  EXPECT_THROW((void)goldschmidt().evaluate(0.0, 1.0, 1.0), Error);
  EXPECT_THROW((void)goldschmidt().evaluate(0.4, 0.6, -1.0), Error);
}

}  // namespace
