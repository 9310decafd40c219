// Lebowitz (mixtures, the multi-phase default) and Ma-Ahmadi g0 (engines/closures/
// RadialDistribution.hpp): hand values (python3), the limits each one has, and refusals instead
// of NaN at and beyond a packing limit.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/Error.hpp"
#include "engines/closures/RadialDistribution.hpp"

using grainbridge::Error;
using namespace grainbridge::closures;

namespace {

TEST(LebowitzG0, OnePhaseHandValuesBelowCarnahanStarling) {
  // 1/eps_g + 3 eps / (2 eps_g^2)
  EXPECT_NEAR(lebowitzG0({0.1}, {1e-3}, 0, 0), 1.0 / 0.9 + 0.3 / (2 * 0.81), 1e-14);
  EXPECT_NEAR(lebowitzG0({0.4}, {1e-3}, 0, 0), 10.0 / 3.0, 1e-14);
  for (const double eps : {0.1, 0.3, 0.5}) EXPECT_LT(lebowitzG0({eps}, {1e-3}, 0, 0), carnahanStarlingG0(eps));
  // Finite up to close packing: no limit below eps_g = 0.
  EXPECT_NEAR(lebowitzG0({0.64}, {1e-3}, 0, 0), 1.0 / 0.36 + 1.92 / (2 * 0.1296), 1e-12);
}

TEST(LebowitzG0, GoldschmidtBinaryMixture) {
  // 1.52 mm + 2.49 mm at 0.2915 each (VALIDATION.md's binary bed), python3.
  const std::vector<double> eps{0.2915, 0.2915}, d{1.52e-3, 2.49e-3};
  EXPECT_NEAR(lebowitzG0(eps, d, 0, 1), 7.427151803736866, 1e-12);
  EXPECT_NEAR(lebowitzG0(eps, d, 1, 0), lebowitzG0(eps, d, 0, 1), 1e-14);  // symmetric
  EXPECT_NEAR(lebowitzG0(eps, d, 0, 0), 6.447593940103182, 1e-12);
  EXPECT_NEAR(lebowitzG0(eps, d, 1, 1), 9.031822251399937, 1e-12);
  // Two phases of one diameter are one phase of their total fraction.
  EXPECT_NEAR(lebowitzG0({0.2, 0.1}, {2e-3, 2e-3}, 0, 1), lebowitzG0({0.3}, {2e-3}, 0, 0), 1e-13);
}

TEST(LebowitzG0, RefusesWhatHasNoVoid) {
  EXPECT_THROW((void)lebowitzG0({0.6, 0.4}, {1e-3, 2e-3}, 0, 1), Error);
  EXPECT_THROW((void)lebowitzG0({-0.1}, {1e-3}, 0, 0), Error);
  EXPECT_THROW((void)lebowitzG0({0.1}, {0.0}, 0, 0), Error);
  EXPECT_THROW((void)lebowitzG0({0.1}, {1e-3}, 0, 1), Error);
  EXPECT_THROW((void)lebowitzG0({std::numeric_limits<double>::quiet_NaN()}, {1e-3}, 0, 0), Error);
}

TEST(DefaultG0, CarnahanStarlingForOnePhaseLebowitzForSeveral) {
  EXPECT_EQ(defaultG0({0.3}, {2e-3}, 0, 0), carnahanStarlingG0(0.3));
  // Two phases, even of one size, switch to Lebowitz (lower than Carnahan-Starling).
  EXPECT_EQ(defaultG0({0.2, 0.1}, {2e-3, 2e-3}, 0, 1), lebowitzG0({0.2, 0.1}, {2e-3, 2e-3}, 0, 1));
  EXPECT_LT(defaultG0({0.2, 0.1}, {2e-3, 2e-3}, 0, 1), carnahanStarlingG0(0.3));
}

TEST(MaAhmadiG0, HandValuesAndTheDiluteLimit) {
  EXPECT_DOUBLE_EQ(maAhmadiG0(0.0), 1.0);
  EXPECT_NEAR(maAhmadiG0(0.1), 1.3037378357622247, 1e-13);
  EXPECT_NEAR(maAhmadiG0(0.3), 2.456661973836026, 1e-13);
  EXPECT_NEAR(maAhmadiG0(0.5), 6.085429269459036, 1e-12);
  EXPECT_NEAR(maAhmadiG0(0.6), 15.83217879369884, 1e-11);
  // Same first-order term as Carnahan-Starling, 1 + 5/2 eps.
  EXPECT_NEAR((maAhmadiG0(1e-5) - 1.0) / 1e-5, 2.5, 1e-3);
  EXPECT_NEAR((carnahanStarlingG0(1e-5) - 1.0) / 1e-5, 2.5, 1e-3);
}

TEST(MaAhmadiG0, DivergesAtItsPackingLimitAndRefusesBeyondIt) {
  EXPECT_GT(maAhmadiG0(std::nextafter(kMaAhmadiPackingLimit, 0.0)), 1e9);
  for (const double bad : {kMaAhmadiPackingLimit, 0.65, 0.9, -0.01, std::numeric_limits<double>::quiet_NaN()}) {
    try {
      (void)maAhmadiG0(bad);
      ADD_FAILURE() << "no error for eps = " << bad;
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("its packing limit"));
    }
  }
}

}  // namespace
