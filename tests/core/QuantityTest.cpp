#include <gtest/gtest.h>

#include <cmath>

#include "core/units/Quantity.hpp"

using namespace grainbridge::core::units;

namespace {
double si(const nlohmann::json& v, Dimension dim, const UnitSystem& sys = UnitSystem::si()) {
  auto r = parseQuantity(v, dim, sys);
  if (auto* e = std::get_if<std::string>(&r)) ADD_FAILURE() << *e;
  return std::holds_alternative<double>(r) ? std::get<double>(r) : NAN;
}
std::string err(const nlohmann::json& v, Dimension dim) {
  auto r = parseQuantity(v, dim, UnitSystem::si());
  return std::holds_alternative<std::string>(r) ? std::get<std::string>(r) : "";
}
}  // namespace

TEST(Quantity, ConvertsUnitStringsToSI) {
  EXPECT_DOUBLE_EQ(si("2.5 mm", Dimension::lengthDim()), 2.5e-3);
  EXPECT_DOUBLE_EQ(si("39 m/s", Dimension::velocity()), 39.0);
  EXPECT_NEAR(si("2.7 g/cm3", Dimension::density()), 2700.0, 1e-9);
  EXPECT_NEAR(si("8e5 dyne/cm", Dimension::stiffness()), 800.0, 1e-9);  // Table 7.1: 800 N/m
  EXPECT_NEAR(si("18 dyne s/cm", Dimension{0, 1, -1}), 0.018, 1e-12);
  EXPECT_NEAR(si("1.8e-5 Pa s", Dimension::viscosity()), 1.8e-5, 1e-15);
  EXPECT_NEAR(si("90 degree", Dimension::none()), M_PI / 2, 1e-12);
  EXPECT_DOUBLE_EQ(si(0.25, Dimension::lengthDim()), 0.25);
}

TEST(Quantity, ReducedUnitsScaleByD0M0T0) {
  // Table 6.1 reduced units: t0 = sqrt(d0/g).
  const auto sys = UnitSystem::reduced(0.002, 1e-5, 9.81);
  const double t0 = std::sqrt(0.002 / 9.81);
  EXPECT_NEAR(si(2e-4, Dimension::timeDim(), sys), 2e-4 * t0, 1e-18);
  EXPECT_NEAR(si(2e5, Dimension::stiffness(), sys), 2e5 * 1e-5 / (t0 * t0), 1e-6);
  // A string with a unit is absolute whatever the system.
  EXPECT_DOUBLE_EQ(si("3 mm", Dimension::lengthDim(), sys), 3e-3);
}

TEST(Quantity, RejectsUnknownAndWrongDimensionUnits) {
  EXPECT_NE(err("2.5 furlongz", Dimension::lengthDim()).find("unknown unit 'furlongz'"), std::string::npos);
  EXPECT_NE(err("2.5 s", Dimension::lengthDim()).find("not a unit of [m]"), std::string::npos);
  EXPECT_NE(err("fast", Dimension::velocity()).find("found \"fast\""), std::string::npos);
  EXPECT_NE(err(true, Dimension::velocity()).find("found boolean"), std::string::npos);
  EXPECT_NE(err("2.5", Dimension::lengthDim()).find("needs a unit"), std::string::npos);
}
