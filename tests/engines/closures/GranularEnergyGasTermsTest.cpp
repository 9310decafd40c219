// Gas terms of the granular-energy equation (engines/closures/GranularEnergyGasTerms, MFIX's Lun
// path): hand values (python3), their zero limits, and the refusal of gamma_slip at theta = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "engines/closures/GranularEnergyGasTerms.hpp"

using namespace grainbridge;
using namespace grainbridge::closures;

namespace {

const GranularEnergyGasTerms::State kState{0.3, 2.49e-3, 2526.0, 2.4781341, 1.8e-5, 0.5, 3000.0};

TEST(GranularEnergyGasTerms, HandValues) {
  const auto r = GranularEnergyGasTerms{}.evaluate(kState);
  EXPECT_NEAR(r.slipProductionCoefficient, 1.1491061919364202e-05, 1e-18);
  EXPECT_NEAR(r.slipProduction(0.02), 8.125407806216931e-05, 1e-17);
  EXPECT_DOUBLE_EQ(r.viscousDissipation(0.02), 180.0);  // 3 beta theta
}

TEST(GranularEnergyGasTerms, VanishWithoutSlipOrDrag) {
  auto s = kState;
  s.slip = 0.0;
  s.beta = 0.0;
  const auto r = GranularEnergyGasTerms{}.evaluate(s);
  EXPECT_EQ(r.slipProductionCoefficient, 0.0);
  EXPECT_EQ(r.viscousDissipation(0.02), 0.0);
  // Production falls as 1/sqrt(theta): quadrupling theta halves it.
  const auto withSlip = GranularEnergyGasTerms{}.evaluate(kState);
  EXPECT_NEAR(withSlip.slipProduction(0.08), 0.5 * withSlip.slipProduction(0.02), 1e-18);
}

TEST(GranularEnergyGasTerms, RefusesGammaSlipAtZeroTemperatureAndBadInputs) {
  const auto r = GranularEnergyGasTerms{}.evaluate(kState);
  EXPECT_THROW((void)r.slipProduction(0.0), Error);
  auto s = kState;
  s.gasViscosity = 0.0;
  EXPECT_THROW((void)GranularEnergyGasTerms{}.evaluate(s), Error);
}

}  // namespace
