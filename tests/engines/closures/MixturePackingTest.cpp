// The packing limit of a mixture (engines/closures/MixturePacking.hpp) against the papers'
// equations written out here for the Goldschmidt binary bed's pair (1.52 and 2.49 mm glass).
#include "engines/closures/MixturePacking.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/Error.hpp"

namespace grainbridge::closures {
namespace {

constexpr double kSmall = 1.52e-3, kLarge = 2.49e-3;

// Yu and Standish (1987), Powder Technol. 52:233, Eqs. 22-25 for two components of equal
// packing P alone, the coarse one first, each half of the solids volume.
double yuStandishHalfHalf(double P) {
  const double r = kSmall / kLarge;                                        // (25)
  const double Pij = P + P * (1.0 - P) * (1.0 - 2.35 * r + 1.35 * r * r);  // (23), r <= 0.741
  const double Xcoarse = 1.0 - (1.0 - r * r) / (2.0 - P);                  // (24): X_12, the fine j > i
  const double Xfine = (1.0 - r * r) / (2.0 - P);                          // (24): X_21, the coarse j < i
  const double coarse = P / (1.0 - (1.0 - P / Pij) * 0.5 / Xcoarse);       // (22), i = 1
  const double fine = P / (1.0 - (1.0 - P / Pij) * 0.5 / Xfine);           // (22), i = 2
  return std::min(coarse, fine);
}

TEST(MixturePacking, YuStandishOfTheBinaryBedsHalfHalfCellIsThePapersValue) {
  const std::vector<double> d{kSmall, kLarge}, P{0.6, 0.6};
  const std::array<double, 2> eps{0.29, 0.29};
  EXPECT_DOUBLE_EQ(yuStandishPacking(eps, d, P), yuStandishHalfHalf(0.6));
  // The number issue 55 quotes: a 50/50 cell packs at about 0.615, eps_g* 0.385 against 0.4.
  EXPECT_NEAR(1.0 - yuStandishPacking(eps, d, P), 0.3851, 1e-4);
  // The order of the phases does not matter.
  const std::vector<double> dSwapped{kLarge, kSmall};
  EXPECT_DOUBLE_EQ(yuStandishPacking(eps, dSwapped, P), yuStandishHalfHalf(0.6));
}

TEST(MixturePacking, YuStandishOfOneKindAloneIsItsOwnPacking) {
  const std::vector<double> d{kSmall, kLarge}, P{0.583, 0.583};
  EXPECT_DOUBLE_EQ(yuStandishPacking(std::array<double, 2>{0.5, 0.0}, d, P), 0.583);
  EXPECT_DOUBLE_EQ(yuStandishPacking(std::array<double, 2>{0.0, 0.5}, d, P), 0.583);
  // Mixed, denser than either alone.
  EXPECT_GT(yuStandishPacking(std::array<double, 2>{0.25, 0.25}, d, P), 0.583 + 0.01);
}

TEST(MixturePacking, FedorsLandelOfTheHalfHalfCellIsThePapersValue) {
  // Fedors and Landel (1979), Powder Technol. 23:225, x_L = 0.5 <= P_L / (P_L + (1 - P_L) P_S):
  const double PL = 0.6, PS = 0.6, r = kSmall / kLarge;
  const double mixed = PL + (1.0 - PL) * PS;
  const double expected = ((PL - PS) + (1.0 - std::sqrt(r)) * (1.0 - PL) * PS) * mixed * 0.5 / PL + PS;
  const std::vector<double> d{kSmall, kLarge}, P{PS, PL};
  EXPECT_DOUBLE_EQ(fedorsLandelPacking(std::array<double, 2>{0.2, 0.2}, d, P), expected);
  EXPECT_NEAR(expected, 0.63674, 1e-5);
  // All coarse: P_L; all fine: P_S.
  EXPECT_DOUBLE_EQ(fedorsLandelPacking(std::array<double, 2>{0.0, 0.3}, d, P), PL);
  EXPECT_DOUBLE_EQ(fedorsLandelPacking(std::array<double, 2>{0.3, 0.0}, d, P), PS);
}

TEST(MixturePacking, OnePhaseAndIdenticalPhasesKeepTheFixedCriticalVoidFraction) {
  const MixturePacking one(PackingLimit::YuStandish, 0.417, {kLarge}, {0.6});
  EXPECT_FALSE(one.byComposition());
  EXPECT_EQ(one.criticalVoidFraction(std::array<double, 1>{0.5}), 0.417);
  // Two identical phases with max packing 1 - 0.417: today's eps_g* whatever the split.
  const MixturePacking identical(PackingLimit::YuStandish, 0.417, {kLarge, kLarge}, {0.583, 0.583});
  EXPECT_TRUE(identical.byComposition());
  for (double share : {0.0, 0.3, 0.5, 1.0}) {
    const std::array<double, 2> eps{0.5 * share, 0.5 * (1.0 - share)};
    EXPECT_DOUBLE_EQ(identical.criticalVoidFraction(eps), 0.417) << share;
  }
  const MixturePacking fixed(PackingLimit::Fixed, 0.417, {kSmall, kLarge}, {});
  EXPECT_EQ(fixed.criticalVoidFraction(std::array<double, 2>{0.3, 0.3}), 0.417);
}

TEST(MixturePacking, CellsTakeTheirCompositionsLimit) {
  const MixturePacking ys(PackingLimit::YuStandish, 0.417, {kSmall, kLarge}, {0.6, 0.6});
  EXPECT_DOUBLE_EQ(ys.criticalVoidFraction(std::array<double, 2>{0.3, 0.3}), 1.0 - yuStandishHalfHalf(0.6));
  // An empty cell: the coarsest phase alone. Round-off below zero is no share.
  EXPECT_DOUBLE_EQ(ys.criticalVoidFraction(std::array<double, 2>{0.0, 0.0}), 1.0 - 0.6);
  EXPECT_DOUBLE_EQ(ys.criticalVoidFraction(std::array<double, 2>{-1e-18, 0.4}), 1.0 - 0.6);
  // Gera: Fedors-Landel held at eps_g* >= 0.36 (x_L = 0.7 packs at 0.652 unbounded).
  const MixturePacking gera(PackingLimit::Gera, 0.417, {kSmall, kLarge}, {0.6, 0.6});
  EXPECT_DOUBLE_EQ(gera.criticalVoidFraction(std::array<double, 2>{0.15, 0.35}), kGeraLeastVoidFraction);
  EXPECT_NEAR(gera.criticalVoidFraction(std::array<double, 2>{0.25, 0.25}), 1.0 - 0.63674, 1e-5);
}

TEST(MixturePacking, RefusesWhatItCannotEvaluate) {
  EXPECT_THROW(MixturePacking(PackingLimit::Gera, 0.417, {1e-3, 2e-3, 3e-3}, {0.6, 0.6, 0.6}), Error);
  EXPECT_THROW(MixturePacking(PackingLimit::YuStandish, 0.417, {1e-3, 2e-3}, {0.6}), Error);
  EXPECT_THROW(MixturePacking(PackingLimit::YuStandish, 0.417, {1e-3, 2e-3}, {0.6, 1.2}), Error);
  const std::vector<double> d{kSmall, kLarge}, P{0.6, 0.6};
  EXPECT_THROW((void)yuStandishPacking(std::array<double, 2>{0.0, 0.0}, d, P), Error);
  EXPECT_THROW((void)fedorsLandelPacking(std::array<double, 3>{0.1, 0.1, 0.1}, std::vector<double>{1, 2, 3},
                                         std::vector<double>{0.6, 0.6, 0.6}),
               Error);
  EXPECT_EQ(packingLimitFromString("yu_standish"), PackingLimit::YuStandish);
  EXPECT_THROW((void)packingLimitFromString("yu-standish"), Error);
}

}  // namespace
}  // namespace grainbridge::closures
