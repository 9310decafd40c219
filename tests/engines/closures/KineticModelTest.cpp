// Model selection by name (engines/closures/KineticModel.hpp), input validation shared by all
// models, and properties every model must have (STYLE.md 8: generic tests over every law).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "engines/closures/KineticModel.hpp"
#include "engines/closures/Lun1984.hpp"
#include "engines/closures/SyamlalAlgebraic.hpp"

using grainbridge::Error;
using namespace grainbridge::closures;
using ::testing::HasSubstr;

namespace {

void expectRel(double actual, double expected, double rel, const std::string& what) {
  EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << what;
}

TEST(KineticModel, NamesRoundTrip) {
  EXPECT_EQ(kineticModelFromString("lun1984"), KineticModelName::Lun1984);
  EXPECT_EQ(kineticModelFromString("syamlal_algebraic"), KineticModelName::SyamlalAlgebraicPrinted);
  EXPECT_EQ(kineticModelFromString("syamlal_algebraic_mfix"), KineticModelName::SyamlalAlgebraicMfix);
  for (const KineticModelName m : kAllKineticModels) EXPECT_EQ(kineticModelFromString(toString(m)), m);
}

TEST(KineticModel, DefaultIsLun1984) { EXPECT_EQ(kDefaultKineticModel, KineticModelName::Lun1984); }

TEST(KineticModel, UnknownNameListsTheValidOnes) {
  for (const std::string bad : {"Lun1984", "lun", "", "syamlal"}) {
    try {
      (void)kineticModelFromString(bad);
      ADD_FAILURE() << "no error for \"" << bad << "\"";
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr("\"" + bad + "\""));
      EXPECT_THAT(e.what(), HasSubstr("\"lun1984\""));
      EXPECT_THAT(e.what(), HasSubstr("\"syamlal_algebraic\""));
      EXPECT_THAT(e.what(), HasSubstr("\"syamlal_algebraic_mfix\""));
    }
  }
}

TEST(KineticModel, EvaluateDispatchesToTheNamedModel) {
  const KineticState s{0.25, 0.03, 2e-3, 2500.0, 0.9, 0.0};
  EXPECT_DOUBLE_EQ(evaluate(KineticModelName::Lun1984, s).shearViscosity, Lun1984{}.evaluate(s).shearViscosity);
  SyamlalAlgebraic mfix;
  mfix.params.viscosityForm = SyamlalViscosityForm::Mfix;
  EXPECT_DOUBLE_EQ(evaluate(KineticModelName::SyamlalAlgebraicPrinted, s).shearViscosity,
                   SyamlalAlgebraic{}.evaluate(s).shearViscosity);
  EXPECT_DOUBLE_EQ(evaluate(KineticModelName::SyamlalAlgebraicMfix, s).shearViscosity, mfix.evaluate(s).shearViscosity);
  // The three really are different models.
  EXPECT_NE(evaluate(KineticModelName::Lun1984, s).shearViscosity,
            evaluate(KineticModelName::SyamlalAlgebraicPrinted, s).shearViscosity);
  EXPECT_NE(evaluate(KineticModelName::SyamlalAlgebraicPrinted, s).shearViscosity,
            evaluate(KineticModelName::SyamlalAlgebraicMfix, s).shearViscosity);
}

// --- properties of every model ---------------------------------------------------------------

std::vector<KineticState> grid() {
  std::vector<KineticState> states;
  for (const double eps : {0.0, 0.01, 0.1, 0.3, 0.5, 0.6}) {
    for (const double e : {0.5, 0.7, 0.9, 1.0}) states.push_back(KineticState{eps, 0.02, 1.5e-3, 2500.0, e, 0.0});
  }
  return states;
}

std::string describe(KineticModelName m, const KineticState& s) {
  return std::string(toString(m)) + " at eps " + std::to_string(s.solidFraction) + ", e " +
         std::to_string(s.restitution);
}

TEST(KineticModelProperties, FiniteAndNonNegativeForRestitutionAtLeastHalf) {
  // Below e = 1/2 some of Lun's factors (3 eta - 2, 4 eta - 3) turn negative and a dense state
  // can give a negative coefficient; the grid stays where all must be >= 0.
  for (const KineticModelName m : kAllKineticModels) {
    for (const KineticState& s : grid()) {
      const KineticTransport t = evaluate(m, s);
      for (const double v : {t.pressure, t.shearViscosity, t.bulkViscosity, t.conductivity, t.dissipationRate}) {
        EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << describe(m, s) << ": " << v;
      }
    }
  }
}

TEST(KineticModelProperties, ElasticSpheresDoNotDissipate) {
  for (const KineticModelName m : kAllKineticModels) {
    for (const KineticState& s : grid()) {
      if (s.restitution != 1.0) continue;
      EXPECT_EQ(evaluate(m, s).dissipationRate, 0.0) << describe(m, s);
    }
  }
}

TEST(KineticModelProperties, ScaleWithGranularTemperature) {
  // At fixed eps, e: p and J carry theta and theta^1.5, the transport coefficients sqrt(theta),
  // which is what lets tabulated closures use p/(rho theta), mu/(rho d sqrt(theta)) (DESIGN.md).
  for (const KineticModelName m : kAllKineticModels) {
    const KineticState s{0.3, 0.01, 1.5e-3, 2500.0, 0.9, 0.0};
    KineticState hot = s;
    hot.granularTemperature = 4.0 * s.granularTemperature;
    const KineticTransport a = evaluate(m, s);
    const KineticTransport b = evaluate(m, hot);
    const std::string name(toString(m));
    expectRel(b.pressure, 4.0 * a.pressure, 1e-13, name + " pressure");
    expectRel(b.shearViscosity, 2.0 * a.shearViscosity, 1e-13, name + " shear viscosity");
    expectRel(b.bulkViscosity, 2.0 * a.bulkViscosity, 1e-13, name + " bulk viscosity");
    expectRel(b.conductivity, 2.0 * a.conductivity, 1e-13, name + " conductivity");
    expectRel(b.dissipationRate, 8.0 * a.dissipationRate, 1e-13, name + " dissipation");
  }
}

TEST(KineticModelProperties, ModelsShareCollisionalBulkViscosityAndDissipation) {
  // Lun's 8 eta/(3 sqrt(pi)) and Eq. 3.24's 4 (1+e)/(3 sqrt(pi)) are the same bulk viscosity,
  // and all take Eq. 5.7 for J; Eq. 3.21 is Lun's pressure without the kinetic rho eps theta.
  for (const KineticState& s : grid()) {
    const KineticTransport lun = evaluate(KineticModelName::Lun1984, s);
    for (const KineticModelName m :
         {KineticModelName::SyamlalAlgebraicPrinted, KineticModelName::SyamlalAlgebraicMfix}) {
      const KineticTransport t = evaluate(m, s);
      expectRel(t.bulkViscosity, lun.bulkViscosity, 1e-13, describe(m, s) + " bulk viscosity");
      expectRel(t.dissipationRate, lun.dissipationRate, 1e-13, describe(m, s) + " dissipation");
      const double kinetic = s.density * s.solidFraction * s.granularTemperature;
      EXPECT_NEAR(t.pressure, lun.pressure - kinetic, 1e-12 * lun.pressure) << describe(m, s);
    }
  }
}

TEST(KineticModelProperties, SecondViscosityIsBulkMinusTwoThirdsShear) {
  for (const KineticModelName m : kAllKineticModels) {
    const KineticTransport t = evaluate(m, KineticState{0.3, 0.01, 1.5e-3, 2500.0, 0.9, 0.0});
    EXPECT_DOUBLE_EQ(t.secondViscosity(), t.bulkViscosity - 2.0 / 3.0 * t.shearViscosity);
  }
}

// --- input validation ------------------------------------------------------------------------

struct BadInput {
  const char* quantity;  // expected in the message
  const char* shown;     // the value as the message prints it
  KineticState state;
};

std::vector<BadInput> badInputs() {
  const KineticState ok{0.2, 0.01, 1e-3, 2500.0, 0.9, 0.0};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<BadInput> bad;
  auto with = [&](const char* quantity, const char* shown, auto set) {
    KineticState s = ok;
    set(s);
    bad.push_back({quantity, shown, s});
  };
  with("solid fraction", "got -0.1", [](KineticState& s) { s.solidFraction = -0.1; });
  with("solid fraction", "got 1", [](KineticState& s) { s.solidFraction = 1.0; });
  with("solid fraction", "got nan", [&](KineticState& s) { s.solidFraction = nan; });
  with("granular temperature", "got -0.5", [](KineticState& s) { s.granularTemperature = -0.5; });
  with("granular temperature", "got inf", [&](KineticState& s) { s.granularTemperature = inf; });
  with("particle diameter", "got 0", [](KineticState& s) { s.diameter = 0.0; });
  with("particle density", "got -2500", [](KineticState& s) { s.density = -2500.0; });
  with("restitution", "got 0", [](KineticState& s) { s.restitution = 0.0; });
  with("restitution", "got 1.01", [](KineticState& s) { s.restitution = 1.01; });
  with("restitution", "got nan", [&](KineticState& s) { s.restitution = nan; });
  with("gas drag coefficient", "got -1", [](KineticState& s) { s.gasDragCoefficient = -1.0; });
  return bad;
}

TEST(KineticModelValidation, EveryModelRefusesBadInputNamingQuantityAndValue) {
  for (const KineticModelName m : kAllKineticModels) {
    for (const BadInput& b : badInputs()) {
      try {
        (void)evaluate(m, b.state);
        ADD_FAILURE() << toString(m) << " accepted bad " << b.quantity << " (" << b.shown << ")";
      } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr(b.quantity)) << toString(m);
        EXPECT_THAT(e.what(), HasSubstr(b.shown)) << toString(m);
      }
    }
  }
}

TEST(KineticModelValidation, AcceptsTheEdgesOfTheValidRanges) {
  for (const KineticModelName m : kAllKineticModels) {
    EXPECT_NO_THROW((void)evaluate(m, KineticState{0.0, 0.0, 1e-3, 2500.0, 1.0, 0.0})) << toString(m);
    EXPECT_NO_THROW((void)evaluate(m, KineticState{0.6, 1.0, 1e-3, 2500.0, 1e-3, 0.0})) << toString(m);
  }
}

}  // namespace
