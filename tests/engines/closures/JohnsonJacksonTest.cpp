// Johnson-Jackson partial slip and wall energy flux (engines/closures/JohnsonJackson, Eqs.
// 5.8-5.10 and 5.21): hand values (python3), the free-slip and elastic-wall limits, the
// rotation model's wall factor, refusals.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "engines/closures/EffectiveRestitution.hpp"
#include "engines/closures/JohnsonJackson.hpp"

using namespace grainbridge;
using namespace grainbridge::closures;

namespace {

JohnsonJackson wall(double specularity = 0.6, double ew = 0.9) {
  JohnsonJackson j;
  j.params.specularity = specularity;
  j.params.maxSolidFraction = 0.583;  // 1 - eps_g* of the Goldschmidt bed
  j.params.wallRestitution = ew;
  return j;
}
const JohnsonJackson::State kState{0.5, 2526.0, 5.0, 0.01, 0.2};

TEST(JohnsonJackson, HandValues) {
  const auto r = wall().evaluate(kState);
  EXPECT_NEAR(r.slipCoefficient, 589.4070146726802, 1e-9);
  EXPECT_NEAR(r.shearStress, 117.88140293453606, 1e-10);
  EXPECT_NEAR(r.slipProduction, 23.576280586907213, 1e-11);
  EXPECT_NEAR(r.wallDissipation, 2.79968331969523, 1e-12);
  EXPECT_NEAR(r.energyFluxIntoFlow(), 23.576280586907213 - 2.79968331969523, 1e-11);
}

TEST(JohnsonJackson, FreeSlipElasticWallAndRestingSolids) {
  const auto smooth = wall(0.0).evaluate(kState);  // specular: no traction, no production
  EXPECT_EQ(smooth.slipCoefficient, 0.0);
  EXPECT_EQ(smooth.slipProduction, 0.0);
  EXPECT_GT(smooth.wallDissipation, 0.0);
  EXPECT_EQ(wall(0.6, 1.0).evaluate(kState).wallDissipation, 0.0);  // elastic wall
  auto resting = kState;
  resting.slipSpeed = 0.0;
  EXPECT_EQ(wall().evaluate(resting).shearStress, 0.0);
}

TEST(JohnsonJackson, RotationModelTakesEq521sFactor) {
  // Wall friction 0.09 of Table 5.1 (e = 0.97, beta0 = 0.33): e_w,eff = 0.87010.
  JohnsonJackson j = wall(0.6, 0.97);
  const double eEff = EffectiveRestitution{{0.09, 0.33}}.evaluate(0.97).effectiveRestitution;
  const double without = j.evaluate(kState).wallDissipation;
  j.params.wallEffectiveRestitution = eEff;
  const double with = j.evaluate(kState).wallDissipation;
  EXPECT_NEAR(with / without, 1.97 * (1.0 - eEff) / (1.0 - 0.97 * 0.97), 1e-13);
  EXPECT_GT(with, 4.0 * without);  // (1 + e)(1 - e_eff) = 0.256 against 1 - e^2 = 0.059
}

TEST(JohnsonJackson, RefusesParametersOutOfRange) {
  EXPECT_THAT([] { (void)JohnsonJackson{}.evaluate(kState); }, ::testing::Throws<Error>());  // no eps_max
  EXPECT_THROW((void)wall(1.5).evaluate(kState), Error);
  EXPECT_THROW((void)wall(0.6, 0.0).evaluate(kState), Error);
  auto bad = kState;
  bad.granularTemperature = -1.0;
  EXPECT_THROW((void)wall().evaluate(bad), Error);
}

}  // namespace
