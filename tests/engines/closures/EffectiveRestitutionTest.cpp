// The particle-rotation model (engines/closures/EffectiveRestitution, Eqs. 5.11-5.19): Table
// 5.1's effective restitutions to 1e-4 (the reference prints them rounded), the frictionless
// limit, the Eq. 5.20 factor against (1 - e_eff^2), and refusals.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "engines/closures/EffectiveRestitution.hpp"

using namespace grainbridge;
using namespace grainbridge::closures;

namespace {

EffectiveRestitution law(double mu, double beta0 = 0.33) { return EffectiveRestitution{{mu, beta0}}; }

TEST(EffectiveRestitution, Table51Values) {
  // e = 0.97, beta0 = 0.33 (VALIDATION.md; python3 of Eqs. 5.12-5.19: 0.825439, 0.862060, 0.870097).
  EXPECT_NEAR(law(0.15).evaluate(0.97).effectiveRestitution, 0.82544, 1e-4);
  EXPECT_NEAR(law(0.10).evaluate(0.97).effectiveRestitution, 0.86206, 1e-4);
  EXPECT_NEAR(law(0.09).evaluate(0.97).effectiveRestitution, 0.87010, 1e-4);
}

TEST(EffectiveRestitution, IntermediateTermsAsComputedOutside) {
  // python3 of Eqs. 5.12-5.18 at e 0.97, mu 0.15, beta0 0.33.
  const auto r = law(0.15).evaluate(0.97);
  EXPECT_NEAR(r.mu0, 0.7776315789473685, 1e-14);
  EXPECT_NEAR(r.a1, 0.3622462932945521, 1e-12);
  EXPECT_NEAR(r.a2, 0.5454245833834596, 1e-12);
  EXPECT_NEAR(r.b1, 0.014021217394681734, 1e-14);
  EXPECT_NEAR(r.b2, 0.10458279071831977, 1e-13);
  EXPECT_NEAR(r.rotationalToTranslational, r.b1 / r.b2, 1e-15);
}

TEST(EffectiveRestitution, FrictionlessSpheresKeepTheirRestitutionAndTheLimitIsContinuous) {
  const auto r = law(0.0).evaluate(0.9);
  EXPECT_EQ(r.effectiveRestitution, 0.9);
  EXPECT_EQ(r.rotationalToTranslational, 0.0);
  EXPECT_NEAR(r.dissipationFactor, 1.0 - 0.81, 1e-15);  // (1 + e)(1 - e) = 1 - e^2
  EXPECT_NEAR(law(1e-7).evaluate(0.9).effectiveRestitution, 0.9, 1e-6);
  // More friction, more loss over the range the model is meant for.
  double previous = 0.9;
  for (const double mu : {0.02, 0.05, 0.1, 0.15, 0.2}) {
    const double eEff = law(mu).evaluate(0.9).effectiveRestitution;
    EXPECT_LT(eEff, previous) << mu;
    previous = eEff;
  }
}

TEST(EffectiveRestitution, Eq520FactorIsNotOneMinusEEffSquared) {
  // (1 + e)(1 - e_eff) as printed, 6 % above (1 - e_eff^2) at e_eff 0.862 (VALIDATION.md).
  const auto r = law(0.10).evaluate(0.97);
  EXPECT_NEAR(r.dissipationFactor, 1.97 * (1.0 - r.effectiveRestitution), 1e-15);
  const double squared = 1.0 - r.effectiveRestitution * r.effectiveRestitution;
  EXPECT_NEAR(r.dissipationFactor / squared - 1.0, 0.058, 0.002);
}

TEST(EffectiveRestitution, RefusesValuesOutOfRange) {
  EXPECT_THROW((void)law(0.1).evaluate(0.0), Error);
  EXPECT_THROW((void)law(0.1).evaluate(1.1), Error);
  EXPECT_THROW((void)law(-0.1).evaluate(0.9), Error);
  EXPECT_THROW((void)law(0.1, 1.5).evaluate(0.9), Error);
  try {
    (void)law(0.1).evaluate(std::nan(""));
    FAIL();
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("normal restitution e must be in (0, 1]"));
  }
}

}  // namespace
