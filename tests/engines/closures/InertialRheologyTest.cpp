// The mu(I) rheology a continuum run takes from DEM (engines/closures/InertialRheology) and the
// frictional viscosity it gives the plastic regime (PlasticRegime with `plastic` mu_i): the law
// and the table, the inertial number of the grains, and the plastic shear stress mu(I) P^p_s.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "engines/closures/InertialRheology.hpp"
#include "engines/closures/PlasticRegime.hpp"

using namespace grainbridge;
using namespace grainbridge::closures;

namespace {

// Goldschmidt's glass (Table 5.1): 1.5 mm, 2526 kg/m3; Jop et al.'s law.
const InertialRheology::Grains kGlass{1.5e-3, 2526.0};
const InertialRheology::Law kJop{0.382, 0.644, 0.279};

TEST(InertialRheology, FittedLawHasItsLimitsAndItsMidpoint) {
  const auto r = InertialRheology::fitted(kGlass, kJop);
  EXPECT_DOUBLE_EQ(r.stressRatio(0.0), 0.382);
  EXPECT_NEAR(r.stressRatio(0.279), 0.5 * (0.382 + 0.644), 1e-15);  // I = I_0: halfway
  EXPECT_NEAR(r.stressRatio(1e9), 0.644, 1e-9);
  EXPECT_LT(r.stressRatio(0.01), r.stressRatio(0.1));
}

TEST(InertialRheology, TableInterpolatesInsideAndHoldsItsEnds) {
  const auto r = InertialRheology::tabulated(kGlass, {0.01, 0.1, 0.3}, {0.30, 0.40, 0.50});
  EXPECT_DOUBLE_EQ(r.stressRatio(0.055), 0.35);
  EXPECT_DOUBLE_EQ(r.stressRatio(0.2), 0.45);
  EXPECT_DOUBLE_EQ(r.stressRatio(0.1), 0.40);
  EXPECT_DOUBLE_EQ(r.stressRatio(0.0), 0.30);  // below the slowest point: its value
  EXPECT_DOUBLE_EQ(r.stressRatio(5.0), 0.50);  // above the fastest: its value
}

TEST(InertialRheology, InertialNumberOfItsGrains) {
  // gamma_dot 100/s, p 2526 Pa: sqrt(p / rho_p) = 1 m/s, I = 100 x 1.5e-3 / 1 = 0.15.
  EXPECT_NEAR(InertialRheology::fitted(kGlass, kJop).inertialNumber(100.0, 2526.0), 0.15, 1e-15);
}

TEST(InertialRheology, RefusesWhatIsNotARheology) {
  EXPECT_THROW((void)InertialRheology::fitted({0.0, 2526.0}, kJop), Error);
  EXPECT_THROW((void)InertialRheology::fitted(kGlass, {0.6, 0.4, 0.3}), Error);  // mu_2 < mu_s
  EXPECT_THROW((void)InertialRheology::fitted(kGlass, {0.3, 0.6, 0.0}), Error);
  EXPECT_THROW((void)InertialRheology::tabulated(kGlass, {}, {}), Error);
  EXPECT_THROW((void)InertialRheology::tabulated(kGlass, {0.1, 0.05}, {0.3, 0.4}), Error);  // not increasing
  EXPECT_THROW((void)InertialRheology::tabulated(kGlass, {0.1, 0.2}, {0.3}), Error);
  EXPECT_THAT([] { (void)InertialRheology::tabulated(kGlass, {0.0, 0.2}, {0.3, 0.4}); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("point 0")));
}

PlasticRegime muOfI(const InertialRheology& rheology) {
  PlasticRegime p;
  p.params.criticalVoidFraction = 0.417;
  p.params.rheology = rheology;
  return p;
}

TEST(PlasticRegime, MuOfIShearStressIsTheStressRatioTimesThePlasticPressure) {
  // Simple shear gamma_dot: I2D = gamma_dot^2 / 4, tau = 2 mu^p D_12 = mu^p gamma_dot.
  const auto rheology = InertialRheology::fitted(kGlass, kJop);
  for (const double gammaDot : {50.0, 500.0, 5000.0}) {
    const auto r = muOfI(rheology).evaluate(0.407, 0.593, 0.25 * gammaDot * gammaDot);
    ASSERT_TRUE(r.plastic);
    EXPECT_NEAR(r.pressure, 0.593 * 1.0e4, 1e-6);
    const double I = gammaDot * 1.5e-3 / std::sqrt(r.pressure / 2526.0);
    EXPECT_NEAR(r.inertialNumber, I, 1e-14 * I);
    EXPECT_NEAR(r.viscosity * gammaDot, rheology.stressRatio(I) * r.pressure, 1e-9 * r.pressure);
  }
}

TEST(PlasticRegime, MuOfIKeepsTheCapAndVanishesWithThePlasticPressure) {
  const auto plastic = muOfI(InertialRheology::fitted(kGlass, kJop));
  EXPECT_EQ(plastic.evaluate(0.407, 0.593, 0.0).viscosity, 100.0);    // no shear: the cap
  EXPECT_EQ(plastic.evaluate(0.407, 0.593, 1e-6).viscosity, 100.0);   // slow shear: I -> 0, capped
  EXPECT_EQ(plastic.evaluate(0.407, 0.0, 1.0).viscosity, 0.0);        // no solids of this phase
  EXPECT_EQ(plastic.evaluate(0.42, 0.58, 1.0).viscosity, 0.0);        // above eps_g*: viscous regime
}

TEST(PlasticRegime, MuOfIWithAConstantRatioIsSchaefferWithThatRatioOnEpsSPStar) {
  // A flat table mu = sin(phi) / eps_s is Schaeffer's viscosity: mu^p = P* sin(phi) / (2 sqrt(I2D)).
  const double eps = 0.593, ratio = 0.5 / eps;
  const auto flat = muOfI(InertialRheology::tabulated(kGlass, {0.1}, {ratio}));
  PlasticRegime schaeffer;
  schaeffer.params.criticalVoidFraction = 0.417;
  for (const double i2d : {1.0e2, 1.0e4, 1.0e6}) {
    EXPECT_NEAR(flat.evaluate(0.407, eps, i2d).viscosity, schaeffer.evaluate(0.407, eps, i2d).viscosity,
                1e-12 * schaeffer.evaluate(0.407, eps, i2d).viscosity);
  }
}

}  // namespace
