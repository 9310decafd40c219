// core::ClosureTable: monotone interpolation in solid fraction, linear in the second variable,
// edge clamping with an out-of-range flag, and refusal of malformed tables.
#include "core/ClosureTable.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
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

// A mixture species' table (issue 60): (total solid fraction, volume share x, restitution).
// f = 2 phi + 3 x + 5 e + 7 x e is linear in phi (which PCHIP reproduces: its slopes are the
// secants) and bilinear in (x, e), so the table returns it exactly between its nodes.
TEST(ClosureTable, AThirdAxisInterpolatesBilinearlyWithTheSecond) {
  const std::vector<double> phi{0.1, 0.2, 0.4}, x{0.25, 0.5, 0.75}, e{0.9, 0.97};
  auto f = [](double p, double s, double r) { return 2 * p + 3 * s + 5 * r + 7 * s * r; };
  std::vector<double> values;
  for (double r : e) {
    for (double s : x) {
      for (double p : phi) values.push_back(f(p, s, r));
    }
  }
  const ClosureTable table("p_theta", phi, "volume_share", x, "restitution", e, values);
  ASSERT_TRUE(table.threeDimensional());
  EXPECT_EQ(table.thirdVariable(), "restitution");
  for (const auto& [p, s, r] : {std::tuple{0.15, 0.3, 0.93}, std::tuple{0.4, 0.75, 0.97}, std::tuple{0.33, 0.6, 0.9}}) {
    const auto v = table(p, s, r);
    EXPECT_TRUE(v.inRange);
    EXPECT_NEAR(v.value, f(p, s, r), 1e-12) << p << " " << s << " " << r;
  }
  // The nodes are the values as given, in the order the header says.
  EXPECT_DOUBLE_EQ(table(0.2, 0.75, 0.97).value, values[(1 * 3 + 2) * 3 + 1]);
  // Outside along the third axis: the edge's value, flagged.
  const auto beyond = table(0.2, 0.5, 0.99);
  EXPECT_FALSE(beyond.inRange);
  EXPECT_NEAR(beyond.value, f(0.2, 0.5, 0.97), 1e-12);
  // A third axis needs a second, and a value per node.
  EXPECT_THROW(ClosureTable("p_theta", phi, "", {}, "restitution", e, std::vector<double>(6, 1.0)), Error);
  EXPECT_THROW(ClosureTable("p_theta", phi, "volume_share", x, "restitution", e, std::vector<double>(9, 1.0)), Error);
  // Its JSON form carries the third axis, and a table without one keeps the hash it had.
  const grainbridge::core::LoadedClosureTable loaded{"mix", "key", "", 0.0, table, {}};
  const auto back = grainbridge::core::loadedClosureTableFromJson(nlohmann::json(loaded));
  EXPECT_EQ(back.table.thirds(), e);
  EXPECT_DOUBLE_EQ(back.table(0.15, 0.3, 0.93).value, table(0.15, 0.3, 0.93).value);
  const ClosureTable plain("p_theta", phi, "volume_share", x, std::vector<double>(values.begin(), values.begin() + 9));
  EXPECT_EQ(nlohmann::json(grainbridge::core::LoadedClosureTable{"m", "k", "", 0.0, plain, {}}).count("thirds"), 0u);
}
