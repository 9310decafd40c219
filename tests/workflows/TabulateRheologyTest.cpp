// The tabulate stage's dense-flow part (TabulateRheology): closure-point summaries become
// mu(I) and phi(I) rows per restitution (each in Jop's or the linear form and as a power law), each with the points as
// measured and the fit of the points with I up to the cap; points without an inertial number stay out; points of
// different grains are refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/Error.hpp"
#include "workflows/stages/TabulateRheology.hpp"

using namespace grainbridge;
using namespace grainbridge::workflows::stages;
using nlohmann::json;
using ::testing::HasSubstr;

namespace {

// A sheared point on mu(I) = 0.1 + 0.3 / (1 + 0.2 / I) and phi(I) = 0.64 - 0.4 I, exactly.
json point(double I, double e, double diameter = 1e-3) {
  return {{"family", "simple_shear"},
          {"restitution", e},
          {"friction", 0.0},
          {"diameter", diameter},
          {"density", 2500.0},
          {"inertial_number", I},
          {"inertial_number_err", 0.0},
          {"stress_ratio", 0.1 + 0.3 / (1.0 + 0.2 / I)},
          {"stress_ratio_err", 0.0},
          {"solid_fraction", 0.64 - 0.4 * I},
          {"solid_fraction_err", 0.0}};
}

const json* rowOf(const TabulatedRheology& r, const std::string& relation, double e) {
  for (const auto& row : r.rows) {
    if (row["relation"] == relation && row["restitution"] == e) return &row;
  }
  return nullptr;
}

}  // namespace

TEST(TabulateRheology, OneMuAndOnePhiRowPerRestitutionWithTheFitOfThePointsBelowTheCap) {
  std::vector<json> points;
  for (double I : {0.01, 0.03, 0.1, 0.2, 0.4}) points.push_back(point(I, 0.9));
  for (double I : {0.02, 0.05, 0.3}) points.push_back(point(I, 0.7));
  points.push_back(point(2.0, 0.9));  // above the cap: tabulated, not fitted
  json unsheared = point(0.1, 0.9);
  unsheared.erase("inertial_number");
  points.push_back(unsheared);  // no inertial number: not in the rheology

  const auto r = tabulateRheology(points, "glass", 0.5);
  ASSERT_EQ(r.rows.size(), 8U);  // per restitution mu(I) and phi(I), each in two forms
  const json* mu09 = rowOf(r, "mu_of_I", 0.9);
  ASSERT_NE(mu09, nullptr);
  EXPECT_EQ((*mu09)["points"], 6);
  EXPECT_EQ((*mu09)["fitted_points"], 5);
  EXPECT_EQ((*mu09)["inertial_numbers_json"].size(), 6U);
  EXPECT_DOUBLE_EQ((*mu09)["inertial_numbers_json"][0].get<double>(), 0.01);  // sorted by I
  EXPECT_NEAR((*mu09)["mu_s"].get<double>(), 0.1, 1e-7);
  EXPECT_NEAR((*mu09)["mu_2"].get<double>(), 0.4, 1e-7);
  EXPECT_NEAR((*mu09)["inertial_number_0"].get<double>(), 0.2, 1e-6);
  EXPECT_EQ((*mu09)["weighted"], 0);  // exact points carry no variance
  const json* phi09 = rowOf(r, "phi_of_I", 0.9);
  ASSERT_NE(phi09, nullptr);
  EXPECT_NEAR((*phi09)["phi_c"].get<double>(), 0.64, 1e-10);
  EXPECT_NEAR((*phi09)["slope"].get<double>(), 0.4, 1e-9);
  // Three points at e = 0.7: phi(I) is fitted, mu(I) (three parameters) is not.
  const json* mu07 = rowOf(r, "mu_of_I", 0.7);
  ASSERT_NE(mu07, nullptr);
  EXPECT_FALSE(mu07->contains("mu_s"));
  EXPECT_TRUE(rowOf(r, "phi_of_I", 0.7)->contains("phi_c"));
  EXPECT_THAT(r.pointsCsv, HasSubstr("glass,mu_of_I,0.9,2,0,"));
  EXPECT_THAT(r.fitsCsv, HasSubstr("glass,phi_of_I,0.7,phi_c,"));
  // The power-law form of phi(I) on points of a straight line: exponent 1, the line's slope and
  // phi_c (issue 61). Its row follows the Jop and linear rows of the same restitution.
  const auto power = std::find_if(r.rows.begin(), r.rows.end(), [](const json& row) {
    return row["relation"] == "phi_of_I" && row["restitution"] == 0.9 &&
           row["form"] == "phi_c_power - phi_amplitude I^phi_exponent";
  });
  ASSERT_NE(power, r.rows.end());
  EXPECT_NEAR((*power)["phi_exponent"].get<double>(), 1.0, 1e-6);
  EXPECT_NEAR((*power)["phi_amplitude"].get<double>(), 0.4, 1e-6);
  EXPECT_NEAR((*power)["phi_c_power"].get<double>(), 0.64, 1e-8);
  EXPECT_THAT(r.fitsCsv, HasSubstr("glass,phi_of_I_power,0.9,phi_exponent,"));
}

TEST(TabulateRheology, PointsWithoutAnInertialNumberGiveNoRows) {
  json p = point(0.1, 0.9);
  p.erase("inertial_number");
  EXPECT_TRUE(tabulateRheology({p}, "t", 0.5).rows.empty());
}

TEST(TabulateRheology, PointsOfDifferentGrainsAreRefused) {
  std::vector<json> points = {point(0.01, 0.9), point(0.1, 0.9, 2e-3)};
  try {
    (void)tabulateRheology(points, "t", 0.5);
    FAIL() << "different diameters were accepted";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("different grains (diameter 0.001 and 0.002 m"));
  }
}
