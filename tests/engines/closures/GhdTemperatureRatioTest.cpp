// The zeroth-order temperature ratio of Garzo, Hrenya and Dufty (homogeneous cooling state,
// zeta_1 = zeta_2): its limits (equal species, elastic grains) and the dilute value for the
// Goldschmidt pair at equal solids volume, from an independent evaluation of the cooling rates
// with chi_ij = 1 (a few lines of Python: T_s / T_l = 0.928818 at alpha 0.9, 0.978855 at 0.97).
#include "engines/closures/GhdTemperatureRatio.hpp"

#include <gtest/gtest.h>

#include "core/Error.hpp"

using namespace grainbridge;
using namespace grainbridge::closures;

TEST(GhdTemperatureRatio, EqualSpeciesShareOneTemperature) {
  EXPECT_NEAR(ghdTemperatureRatio({{0.1, 1e-3, 2500.0}, {0.2, 1e-3, 2500.0}}, 0.8), 1.0, 1e-12);
}

TEST(GhdTemperatureRatio, ElasticGrainsEquipartition) {
  EXPECT_NEAR(ghdTemperatureRatio({{0.1, 1.52e-3, 2523.0}, {0.1, 2.49e-3, 2526.0}}, 1.0), 1.0, 1e-10);
}

TEST(GhdTemperatureRatio, TheDiluteGoldschmidtPairMatchesAnIndependentEvaluation) {
  // 2e-6 of each: chi_ij - 1 is of order 1e-5, below the tolerance.
  const std::vector<CoolingSpecies> dilute{{2e-6, 1.52e-3, 2523.0}, {2e-6, 2.49e-3, 2523.0}};
  EXPECT_NEAR(ghdTemperatureRatio(dilute, 0.9), 0.928818, 2e-5);
  EXPECT_NEAR(ghdTemperatureRatio(dilute, 0.97), 0.978855, 2e-5);
  // The lighter species colder in energy, the more so the more inelastic.
  const std::vector<CoolingSpecies> dense{{0.15, 1.52e-3, 2523.0}, {0.15, 2.49e-3, 2526.0}};
  EXPECT_LT(ghdTemperatureRatio(dense, 0.7), ghdTemperatureRatio(dense, 0.9));
  EXPECT_LT(ghdTemperatureRatio(dense, 0.9), 1.0);
}

TEST(GhdTemperatureRatio, RefusesWhatItCannotEvaluate) {
  EXPECT_THROW((void)ghdTemperatureRatio({{0.1, 1e-3, 2500.0}}, 0.9), Error);
  EXPECT_THROW((void)ghdTemperatureRatio({{0.1, 1e-3, 2500.0}, {0.1, 1e-3, 2500.0}}, 1.2), Error);
  EXPECT_THROW((void)ghdTemperatureRatio({{0.6, 1e-3, 2500.0}, {0.5, 1e-3, 2500.0}}, 0.9), Error);
  EXPECT_THROW((void)ghdTemperatureRatio({{0.1, 0.0, 2500.0}, {0.1, 1e-3, 2500.0}}, 0.9), Error);
}
