// core::ClosureTable: monotone interpolation in solid fraction, linear in the second variable,
// edge clamping with an out-of-range flag, and refusal of malformed tables.
#include "core/ClosureTable.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/Error.hpp"
#include "core/LoadedClosureTable.hpp"

using grainbridge::Error;
using grainbridge::core::ClosureTable;

namespace {

// A closure shaped like p/(rho theta) near random close packing: steep, monotone, convex.
double steep(double eps) { return 1.0 + 4.0 * eps * (1.0 - eps / 2.0) / std::pow(1.0 - eps / 0.64, 2); }

const std::vector<double> kSolidFractions = {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.55, 0.6};

std::vector<double> sampled(double (*f)(double)) {
  std::vector<double> v;
  for (double x : kSolidFractions) v.push_back(f(x));
  return v;
}

}  // namespace

TEST(ClosureTable, PassesThroughItsNodes) {
  const ClosureTable table("p_star", kSolidFractions, sampled(steep));
  for (double x : kSolidFractions) {
    const auto r = table(x);
    EXPECT_TRUE(r.inRange);
    EXPECT_DOUBLE_EQ(r.value, steep(x)) << "at solid fraction " << x;
  }
}

TEST(ClosureTable, ReproducesLinearDataExactly) {
  const ClosureTable table("q", kSolidFractions, sampled([](double x) { return 3.0 - 2.0 * x; }));
  for (double x = 0.05; x <= 0.6; x += 0.0137) EXPECT_NEAR(table(x).value, 3.0 - 2.0 * x, 1e-14) << x;
}

TEST(ClosureTable, MonotoneDataGiveAMonotoneInterpolantWithoutOvershoot) {
  // An ordinary cubic spline may overshoot where the data steepen; PCHIP must not.
  const ClosureTable table("p_star", kSolidFractions, sampled(steep));
  double previous = table(0.05).value;
  for (double x = 0.05; x <= 0.6; x += 1e-4) {
    const double v = table(x).value;
    EXPECT_GE(v, previous - 1e-12) << "not monotone at solid fraction " << x;
    previous = v;
  }
  // And close to the smooth function it samples between the nodes.
  EXPECT_NEAR(table(0.25).value / steep(0.25), 1.0, 0.02);
}

TEST(ClosureTable, IsLinearInTheSecondVariable) {
  const std::vector<double> e = {0.7, 0.8, 0.9};
  std::vector<double> values;
  for (double ee : e) {
    for (double x : kSolidFractions) values.push_back(steep(x) * (1.0 + ee));
  }
  const ClosureTable table("p_star", kSolidFractions, "restitution", e, values);
  EXPECT_TRUE(table.twoDimensional());
  for (double x : {0.07, 0.33, 0.58}) {
    const double row07 = table(x, 0.7).value;
    const double row08 = table(x, 0.8).value;
    EXPECT_NEAR(table(x, 0.75).value, 0.5 * (row07 + row08), 1e-12);
    EXPECT_NEAR(table(x, 0.725).value, 0.75 * row07 + 0.25 * row08, 1e-12);
  }
  EXPECT_DOUBLE_EQ(table(0.3, 0.9).value, steep(0.3) * 1.9);
}

TEST(ClosureTable, OutsideTheTableItClampsToTheEdgeAndSaysSo) {
  const std::vector<double> e = {0.7, 0.9};
  std::vector<double> values;
  for (double ee : e) {
    for (double x : kSolidFractions) values.push_back(steep(x) * ee);
  }
  const ClosureTable table("p_star", kSolidFractions, "restitution", e, values);
  const auto below = table(0.01, 0.8);
  EXPECT_FALSE(below.inRange);
  EXPECT_DOUBLE_EQ(below.value, table(0.05, 0.8).value);
  const auto above = table(0.3, 0.97);
  EXPECT_FALSE(above.inRange);
  EXPECT_DOUBLE_EQ(above.value, table(0.3, 0.9).value);
  EXPECT_TRUE(table(0.6, 0.7).inRange);  // the edges themselves are inside
}

TEST(ClosureTable, RefusesMalformedTablesNamingTheProblem) {
  auto message = [](auto&& make) {
    try {
      make();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([] {
              ClosureTable("p_star", {0.1, 0.3, 0.2}, {1, 2, 3});
            }).find("strictly increasing"),
            std::string::npos);
  EXPECT_NE(message([] {
              ClosureTable("p_star", {0.1, 0.2}, {1, 2, 3});
            }).find("3 values for a 2 x 1 grid"),
            std::string::npos);
  EXPECT_NE(message([] { ClosureTable("p_star", {0.1, 0.2}, {1, NAN}); }).find("not finite"), std::string::npos);
  EXPECT_NE(message([] {
              ClosureTable("eta_star", {0.1, 0.2}, "restitution", {0.9, 0.8}, {1, 2, 3, 4});
            }).find("restitution axis must be strictly increasing"),
            std::string::npos);
}

// A table travels to worker ranks as JSON inside the instance task and comes back whole.
TEST(LoadedClosureTable, RoundTripsThroughJsonAndRefusesAMalformedRecord) {
  const grainbridge::core::LoadedClosureTable loaded{
      "shear", "key1", "", 0.3,
      grainbridge::core::ClosureTable("p_theta", {0.1, 0.2, 0.3}, "restitution", {0.7, 0.9},
                                      {1.0, 2.0, 3.0, 1.5, 2.5, 3.5}),
      {0.1, 0.2, 0.3, 0.15, 0.25, 0.35}};
  const nlohmann::json j = loaded;
  const auto back = grainbridge::core::loadedClosureTableFromJson(j);
  EXPECT_EQ(back.name, "shear");
  EXPECT_EQ(back.runKey, "key1");
  EXPECT_EQ(back.uncertainties, loaded.uncertainties);
  EXPECT_DOUBLE_EQ(back.friction, 0.3);
  EXPECT_EQ(back.table.values(), loaded.table.values());
  EXPECT_EQ(back.table.seconds(), loaded.table.seconds());
  EXPECT_EQ(grainbridge::core::contentSha256(back.table), grainbridge::core::contentSha256(loaded.table));
  // Another value, another hash.
  nlohmann::json changed = j;
  changed["values"][0] = 1.25;
  EXPECT_NE(grainbridge::core::contentSha256(grainbridge::core::loadedClosureTableFromJson(changed).table),
            grainbridge::core::contentSha256(loaded.table));
  nlohmann::json missing = j;
  missing.erase("values");
  EXPECT_THROW((void)grainbridge::core::loadedClosureTableFromJson(missing), grainbridge::Error);
  nlohmann::json short_ = j;
  short_["values"] = {1.0};
  EXPECT_THROW((void)grainbridge::core::loadedClosureTableFromJson(short_), grainbridge::Error);
}
