// A realisation of a measured closure table within its errors (core/ClosureTableDraw, issue 31):
// the drawn nodes have the stated means and standard errors and are independent, a zero error
// leaves its node bit for bit, and a draw is reproducible from its seed.
#include "core/ClosureTableDraw.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/Error.hpp"

using namespace grainbridge;
using namespace grainbridge::core;

namespace {

// p/(rho theta) of a frictionless sweep, with errors of 2-10 %.
ClosureTable synthetic() { return ClosureTable("p_theta", {0.1, 0.3, 0.5}, {1.5, 4.0, 12.0}); }
const std::vector<double> kErrors{0.15, 0.2, 0.24};

TEST(ClosureTableDraw, NodesHaveTheStatedMeanAndStandardErrorAndAreIndependent) {
  const ClosureTable nominal = synthetic();
  constexpr int kDraws = 1000;
  std::vector<double> sum(3, 0.0), sum2(3, 0.0);
  double cross = 0.0;
  for (int s = 0; s < kDraws; ++s) {
    const auto v = drawClosureTable(nominal, kErrors, static_cast<std::uint64_t>(s)).values();
    for (std::size_t k = 0; k < 3; ++k) {
      const double dev = v[k] - nominal.values()[k];
      sum[k] += dev;
      sum2[k] += dev * dev;
    }
    cross += (v[0] - nominal.values()[0]) * (v[1] - nominal.values()[1]) / (kErrors[0] * kErrors[1]);
  }
  for (std::size_t k = 0; k < 3; ++k) {
    const double mean = sum[k] / kDraws;
    const double sd = std::sqrt((sum2[k] - kDraws * mean * mean) / (kDraws - 1));
    EXPECT_LT(std::abs(mean), 3.0 * kErrors[k] / std::sqrt(kDraws)) << "node " << k;
    EXPECT_LT(std::abs(sd - kErrors[k]), 3.0 * kErrors[k] / std::sqrt(2.0 * (kDraws - 1))) << "node " << k;
  }
  EXPECT_LT(std::abs(cross / kDraws), 3.0 / std::sqrt(kDraws));  // correlation of two nodes
}

TEST(ClosureTableDraw, ZeroErrorsGiveTheNominalTableBitForBit) {
  const ClosureTable nominal("j_theta", {0.1, 0.3}, "restitution", {0.7, 0.9}, {1.0, 2.0, 3.0, 4.0});
  const ClosureTable drawn = drawClosureTable(nominal, std::vector<double>(4, 0.0), 42);
  EXPECT_EQ(drawn.values(), nominal.values());
  EXPECT_TRUE(drawn.twoDimensional());
  EXPECT_EQ(drawn(0.2, 0.8).value, nominal(0.2, 0.8).value);
}

TEST(ClosureTableDraw, ASeedGivesOneDrawAndTheQuantityItsOwnStream) {
  const ClosureTable nominal = synthetic();
  EXPECT_EQ(drawClosureTable(nominal, kErrors, 7).values(), drawClosureTable(nominal, kErrors, 7).values());
  EXPECT_NE(drawClosureTable(nominal, kErrors, 7).values(), drawClosureTable(nominal, kErrors, 8).values());
  // Another quantity with the same seed draws other deviates: the tables of one sample are independent.
  const ClosureTable eta("eta_theta", nominal.solidFractions(), nominal.values());
  EXPECT_NE(drawClosureTable(eta, kErrors, 7).values(), drawClosureTable(nominal, kErrors, 7).values());
}

TEST(ClosureTableDraw, DrawsStayPositiveAndBadErrorsAreRefused) {
  // An error as large as the value: the truncated normal keeps every draw above zero.
  const ClosureTable nominal("p_theta", {0.1, 0.2}, {1.0, 1.0});
  for (std::uint64_t s = 0; s < 200; ++s) {
    const ClosureTable drawn = drawClosureTable(nominal, std::vector<double>{1.0, 1.0}, s);
    for (const double v : drawn.values()) EXPECT_GT(v, 0.0);
  }
  EXPECT_THAT([&] { (void)drawClosureTable(nominal, std::vector<double>{0.1}, 1); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("1 standard errors for 2 values")));
  EXPECT_THAT([&] { (void)drawClosureTable(nominal, std::vector<double>{0.1, -0.1}, 1); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("node 1")));
}

}  // namespace

// Issue 63: a joint draw of two tables whose nodes are correlated as recorded (0.9 at the first
// node, -0.5 at the second, none at the third) gives those correlations and keeps each table's
// errors; tables without correlations are drawn as drawClosureTable draws them, bit for bit; a
// coefficient outside [-1, 1] is refused.
TEST(ClosureTableDraw, AJointDrawCorrelatesANodesQuantitiesAsRecorded) {
  const ClosureTable p = synthetic();
  const ClosureTable eta("eta_theta", {0.1, 0.3, 0.5}, {0.6, 1.2, 3.0});
  const std::vector<double> etaErrors{0.03, 0.06, 0.15};
  const std::map<std::string, std::vector<double>> pWithEta{{"eta_theta", {0.9, -0.5, 0.0}}};
  const std::vector<TableToDraw> tables{{&p, kErrors, &pWithEta}, {&eta, etaErrors, nullptr}};
  constexpr int kDraws = 2000;
  std::vector<double> sumP(3), sumE(3), sumPP(3), sumEE(3), sumPE(3);
  for (int s = 0; s < kDraws; ++s) {
    const auto drawn = drawClosureTablesJointly(tables, static_cast<std::uint64_t>(s));
    ASSERT_EQ(drawn.size(), 2u);
    for (std::size_t k = 0; k < 3; ++k) {
      const double a = (drawn[0].values()[k] - p.values()[k]) / kErrors[k];
      const double b = (drawn[1].values()[k] - eta.values()[k]) / etaErrors[k];
      sumP[k] += a, sumE[k] += b, sumPP[k] += a * a, sumEE[k] += b * b, sumPE[k] += a * b;
    }
  }
  const std::vector<double> expected{0.9, -0.5, 0.0};
  for (std::size_t k = 0; k < 3; ++k) {
    const double n = kDraws;
    const double r = (sumPE[k] / n - sumP[k] / n * sumE[k] / n) /
                     std::sqrt((sumPP[k] / n - std::pow(sumP[k] / n, 2)) * (sumEE[k] / n - std::pow(sumE[k] / n, 2)));
    EXPECT_NEAR(r, expected[k], 3.0 * (1.0 - expected[k] * expected[k]) / std::sqrt(n) + 0.01) << "node " << k;
    EXPECT_NEAR(std::sqrt(sumPP[k] / n), 1.0, 0.05) << "node " << k;  // each keeps its own error
    EXPECT_NEAR(std::sqrt(sumEE[k] / n), 1.0, 0.05) << "node " << k;
  }
  // Without correlations: each table on its own stream, as drawClosureTable.
  const std::vector<TableToDraw> independent{{&p, kErrors, nullptr}, {&eta, etaErrors, nullptr}};
  const auto drawn = drawClosureTablesJointly(independent, 11);
  EXPECT_EQ(drawn[0].values(), drawClosureTable(p, kErrors, 11).values());
  EXPECT_EQ(drawn[1].values(), drawClosureTable(eta, etaErrors, 11).values());
  const std::map<std::string, std::vector<double>> bad{{"eta_theta", {1.5, 0.0, 0.0}}};
  const std::vector<TableToDraw> refused{{&p, kErrors, &bad}, {&eta, etaErrors, nullptr}};
  EXPECT_THROW((void)drawClosureTablesJointly(refused, 1), Error);
}
