// A tabulated closure scales its dimensionless table value by the local state, and outside the
// table does exactly what its out-of-range policy says: error, edge value, or kinetic theory.
#include "engines/closures/TabulatedClosure.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"

using namespace grainbridge;
using namespace grainbridge::closures;
using ::testing::HasSubstr;

namespace {

KineticState state(double solidFraction, double restitution = 0.9) {
  KineticState s;
  s.solidFraction = solidFraction;
  s.granularTemperature = 0.04;  // m^2/s^2
  s.diameter = 2e-3;
  s.density = 2500.0;
  s.restitution = restitution;
  return s;
}

// p/(rho theta) of lun1984 at e = 0.9, tabulated at a few solid fractions.
core::ClosureTable lunPressureTable() {
  std::vector<double> x = {0.05, 0.1, 0.2, 0.3, 0.4};
  std::vector<double> v;
  for (double eps : x) {
    const auto s = state(eps);
    v.push_back(evaluate(KineticModelName::Lun1984, s).pressure / (s.density * s.granularTemperature));
  }
  return core::ClosureTable("p_theta", x, v);
}

}  // namespace

TEST(TabulatedClosure, InsideTheTableTheValueIsTheTableTimesTheLocalScale) {
  const TabulatedClosure closure(lunPressureTable(), OutOfRangePolicy::Error);
  const auto at = closure.evaluate(state(0.2));
  EXPECT_EQ(at.source, ClosureValue::Source::Table);
  EXPECT_NEAR(at.value / evaluate(KineticModelName::Lun1984, state(0.2)).pressure, 1.0, 1e-12);
  // Between nodes it is the interpolated table value times rho theta, whatever theta is.
  KineticState hot = state(0.25);
  hot.granularTemperature = 0.36;
  EXPECT_NEAR(closure.evaluate(hot).value, closure.table()(0.25).value * hot.density * 0.36, 1e-9);
  EXPECT_EQ(closure.outOfRangeCount(), 0);
}

TEST(TabulatedClosure, ErrorPolicyRefusesAStateOutsideTheTableNamingItAndTheRange) {
  const TabulatedClosure closure(lunPressureTable(), OutOfRangePolicy::Error);
  try {
    (void)closure.evaluate(state(0.5));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("solid fraction 0.5 is outside the p_theta table (solid fraction 0.05 to 0.4)"));
    EXPECT_THAT(e.what(), HasSubstr("policy is error"));
  }
  EXPECT_EQ(closure.outOfRangeCount(), 1);
}

TEST(TabulatedClosure, ClampPolicyUsesTheTableEdgeAtTheLocalScale) {
  const TabulatedClosure closure(lunPressureTable(), OutOfRangePolicy::Clamp);
  const auto below = closure.evaluate(state(0.01));
  EXPECT_EQ(below.source, ClosureValue::Source::TableEdge);
  EXPECT_DOUBLE_EQ(below.value, closure.table()(0.05).value * 2500.0 * 0.04);
  const auto above = closure.evaluate(state(0.55));
  EXPECT_DOUBLE_EQ(above.value, closure.table()(0.4).value * 2500.0 * 0.04);
  EXPECT_EQ(closure.outOfRangeCount(), 2);
}

TEST(TabulatedClosure, KineticTheoryPolicyFallsBackToTheModelOutsideOnly) {
  // A table deliberately twice lun1984, so a fallback is told apart from the table.
  auto lun = lunPressureTable();
  std::vector<double> doubled;
  for (double eps : lun.solidFractions()) doubled.push_back(2.0 * lun(eps).value);
  const TabulatedClosure closure(core::ClosureTable("p_theta", lun.solidFractions(), doubled),
                                 OutOfRangePolicy::KineticTheory, KineticModelName::Lun1984);
  const auto inside = closure.evaluate(state(0.3));
  EXPECT_EQ(inside.source, ClosureValue::Source::Table);
  EXPECT_NEAR(inside.value / evaluate(KineticModelName::Lun1984, state(0.3)).pressure, 2.0, 1e-12);
  const auto outside = closure.evaluate(state(0.5));
  EXPECT_EQ(outside.source, ClosureValue::Source::KineticTheory);
  EXPECT_DOUBLE_EQ(outside.value, evaluate(KineticModelName::Lun1984, state(0.5)).pressure);
  (void)closure.evaluate(state(0.6));
  EXPECT_EQ(closure.outOfRangeCount(), 2);
}

TEST(TabulatedClosure, ATwoDimensionalTableIsOutOfRangeInRestitutionToo) {
  const std::vector<double> x = {0.1, 0.2};
  const std::vector<double> e = {0.8, 0.9};
  const TabulatedClosure closure(core::ClosureTable("eta_theta", x, "restitution", e, {1.0, 2.0, 3.0, 4.0}),
                                 OutOfRangePolicy::Clamp);
  const auto s = state(0.1, 0.97);
  const auto r = closure.evaluate(s);
  EXPECT_EQ(r.source, ClosureValue::Source::TableEdge);
  EXPECT_DOUBLE_EQ(r.value, 3.0 * s.density * s.diameter * std::sqrt(s.granularTemperature));
}

TEST(TabulatedClosure, RefusesTablesAContinuumEngineCannotUse) {
  EXPECT_THROW(TabulatedClosure(core::ClosureTable("p_shear", {0.1, 0.2}, {1, 2}), OutOfRangePolicy::Clamp), Error);
  EXPECT_THROW(TabulatedClosure(core::ClosureTable("p_theta", {0.1, 0.2}, "friction", {0.0, 0.5}, {1, 2, 3, 4}),
                                OutOfRangePolicy::Clamp),
               Error);
  EXPECT_EQ(outOfRangePolicyFromString("kinetic_theory"), OutOfRangePolicy::KineticTheory);
  EXPECT_THROW((void)outOfRangePolicyFromString("fallback"), Error);
}
