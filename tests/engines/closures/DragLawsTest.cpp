// Generic checks every gas-solids drag law of engines/closures' list passes (STYLE.md 8): a law
// added to DragLaws runs them without a line here. What DragCoefficients holds (DragState.hpp):
// beta = eps_s (beta / eps_s) and the per-particle coefficient pi d^3 (beta / eps_s) / (6 eps_g),
// so for every law
//   - dilute limit: beta -> 0 as eps_s -> 0 while the lone particle keeps a finite, positive
//     coefficient, reached continuously;
//   - positivity: both coefficients finite and > 0 for eps_s > 0, zero slip included (the
//     Stokes limit), and the zero-slip value is the limit of small slips;
//   - the two coefficients are one law: particle = pi d^3 beta / (6 eps_g eps_s);
//   - continuity in eps_g except at the switches the law declares, where beta jumps by the
//     declared amount (Eq. 7.30 at 0.8 by construction, Eq. 3.13 at 0.85 by Eq. 3.14's misfit);
//   - a law with a condition on its parameters (Eq. 3.14) accepts its defaults, names one of its
//     parameters, and with the condition exactly met is continuous at its switch;
//   - bad states are refused.
// Values of particular laws against outside computations are in GasSolidsDragTest.cpp.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/Error.hpp"
#include "engines/closures/GasSolidsDrag.hpp"

using namespace grainbridge;
using namespace grainbridge::closures;

namespace {

template <class List>
struct ToTestingTypes;
template <class... L>
struct ToTestingTypes<TypeList<L...>> {
  using type = ::testing::Types<L...>;
};

template <class Law>
class DragLawTest : public ::testing::Test {};
TYPED_TEST_SUITE(DragLawTest, ToTestingTypes<DragLaws>::type);

constexpr double kRhoG = 1.2, kMuG = 1.8e-5;
DragState state(double epsG, double epsS, double d, double slip) { return {epsG, epsS, d, kRhoG, kMuG, slip}; }

// Is eps_g within one scan step above a switch the law declares? Returns the switch.
template <class Law>
const DragSwitch* switchBetween(double lo, double hi) {
  for (const auto& s : Law::switches) {
    if (lo <= s.voidFraction && s.voidFraction < hi) return &s;
  }
  return nullptr;
}

TYPED_TEST(DragLawTest, DeclaresWhatTheCatalogAndTheStagesRead) {
  using Law = TypeParam;
  EXPECT_FALSE(std::string(Law::name).empty());
  EXPECT_FALSE(std::string(Law::doc).empty());
  EXPECT_THAT(std::string(Law::equations), ::testing::HasSubstr("Eq"));
  EXPECT_FALSE(std::string(Law::source).empty());
  const Law law;
  for (const auto& p : Law::parameters) {
    EXPECT_TRUE(std::isfinite(law.params.*p.member)) << p.key;
    if (p.positive) {
      EXPECT_GT(law.params.*p.member, 0.0) << p.key << ": its default is out of its range";
    }
  }
  EXPECT_EQ(GasSolidsDrag::byName(Law::name).law.index(), DragLaw(Law{}).index());
}

TYPED_TEST(DragLawTest, DiluteLimitLeavesALoneParticleItsDrag) {
  const TypeParam law;
  for (double d : {1e-4, 2.5e-3}) {
    for (double slip : {0.0, 0.1, 1.0, 5.0}) {
      const DragCoefficients lone = law.evaluate(state(1.0, 0.0, d, slip));
      EXPECT_EQ(lone.beta, 0.0) << d << ", " << slip;
      EXPECT_GT(lone.particle, 0.0) << d << ", " << slip;
      EXPECT_TRUE(std::isfinite(lone.particle));
      // eps_s -> 0 continuously: beta ~ eps_s, the particle's coefficient stays.
      const double epsS = 1e-9;
      const DragCoefficients near = law.evaluate(state(1.0 - epsS, epsS, d, slip));
      EXPECT_NEAR(near.particle, lone.particle, 1e-6 * lone.particle) << d << ", " << slip;
      EXPECT_LT(near.beta, 1e-6 * lone.particle * 6.0 / (M_PI * d * d * d)) << d << ", " << slip;
    }
  }
}

TYPED_TEST(DragLawTest, PositiveFiniteAndOneLawInBothForms) {
  const TypeParam law;
  for (double epsG = 0.36; epsG <= 1.0; epsG += 0.04) {
    for (double slip : {0.0, 1e-3, 0.1, 1.0, 10.0}) {
      for (double d : {1e-4, 2.5e-3}) {
        const double epsS = 0.999 * (1.0 - epsG) + 1e-6;
        const DragCoefficients c = law.evaluate(state(epsG, epsS, d, slip));
        ASSERT_TRUE(std::isfinite(c.beta) && c.beta > 0.0) << epsG << ", " << slip << ", " << d;
        ASSERT_TRUE(std::isfinite(c.particle) && c.particle > 0.0) << epsG << ", " << slip << ", " << d;
        EXPECT_NEAR(c.particle, M_PI * d * d * d * c.beta / (6.0 * epsG * epsS), 1e-12 * c.particle);
      }
    }
  }
}

TYPED_TEST(DragLawTest, ZeroSlipIsTheLimitOfSmallSlips) {
  const TypeParam law;
  for (double epsG : {0.4, 0.6, 0.9, 1.0}) {
    const double epsS = std::max(0.0, 1.0 - epsG);
    const double at0 = law.evaluate(state(epsG, epsS, 2.5e-3, 0.0)).particle;
    // Syamlal-O'Brien approaches it as sqrt(Re): 1e-12 m/s is Re 1.7e-10.
    const double near0 = law.evaluate(state(epsG, epsS, 2.5e-3, 1e-12)).particle;
    EXPECT_NEAR(near0, at0, 1e-4 * at0) << epsG;
  }
}

TYPED_TEST(DragLawTest, ContinuousInVoidFractionExceptAtItsDeclaredSwitches) {
  using Law = TypeParam;
  const Law law;
  // A scan step small enough that a smooth law moves by much less than any declared jump, and
  // each declared switch checked right at it (its value and the next double above). The scan
  // reads the per-particle coefficient, beta / eps_s up to a smooth factor, which stays finite
  // as eps_s = 1 - eps_g vanishes.
  const double step = 1e-4;
  for (double epsG = 0.36; epsG + step <= 1.0; epsG += step) {
    if (switchBetween<Law>(epsG, epsG + step) != nullptr) continue;
    const double a = law.evaluate(switchReferenceState(epsG)).particle;
    const double b = law.evaluate(switchReferenceState(epsG + step)).particle;
    ASSERT_LT(std::abs(b / a - 1.0), 2e-3)
        << Law::name << " jumps between eps_g " << epsG << " and " << epsG + step << " where it declares no switch";
  }
  for (const auto& s : Law::switches) {
    const double below = law.evaluate(switchReferenceState(s.voidFraction)).beta;
    const double above = law.evaluate(switchReferenceState(std::nextafter(s.voidFraction, 2.0))).beta;
    EXPECT_NEAR((above - below) / below, s.relativeJump, 1e-3 * std::abs(s.relativeJump) + 1e-9)
        << Law::name << " at eps_g " << s.voidFraction;
  }
}

TYPED_TEST(DragLawTest, AParameterConditionAcceptsTheDefaultsAndNamesAParameter) {
  using Law = TypeParam;
  const Law law;
  const DragParamsProblem atDefaults = paramsProblem<Law>(law.params);
  EXPECT_EQ(atDefaults.why, "") << Law::name;
  if constexpr (requires { Law::check(law.params); }) {
    // Each parameter far off its default: some condition must fail, and it names a parameter.
    bool refused = false;
    for (const auto& p : Law::parameters) {
      typename Law::Params off = law.params;
      off.*p.member *= 1.5;
      const DragParamsProblem problem = Law::check(off);
      if (problem.why.empty()) continue;
      refused = true;
      EXPECT_TRUE(std::any_of(Law::parameters.begin(), Law::parameters.end(),
                              [&](const auto& q) { return problem.key == q.key; }))
          << Law::name << ": the problem names \"" << problem.key << "\", not a parameter";
    }
    EXPECT_TRUE(refused) << Law::name << " declares a check that refuses nothing";
  }
}

TYPED_TEST(DragLawTest, RefusesBadStates) {
  const TypeParam law;
  EXPECT_THROW((void)law.evaluate(state(0.0, 0.5, 1e-3, 1.0)), Error);
  EXPECT_THROW((void)law.evaluate(state(0.5, -0.1, 1e-3, 1.0)), Error);
  EXPECT_THROW((void)law.evaluate(state(0.5, 0.5, 0.0, 1.0)), Error);
  EXPECT_THROW((void)law.evaluate(state(0.5, 0.5, 1e-3, -1.0)), Error);
  EXPECT_THROW((void)law.evaluate(state(0.5, 0.5, 1e-3, std::numeric_limits<double>::quiet_NaN())), Error);
}

// Eq. 3.14 where it applies: with D from C exactly, B of Eq. 3.13 (and so beta) is continuous at
// the switch syamlal_obrien declares; the declared jump at the defaults is Eq. 3.14's misfit.
TEST(DragLaws, SyamlalOBrienIsContinuousAtItsSwitchWhenEq314Holds) {
  SyamlalOBrien law;
  law.params.d = std::log(law.params.c * std::pow(0.85, 1.28)) / std::log(0.85);
  EXPECT_NEAR(law.params.continuityResidual(), 0.0, 1e-14);
  EXPECT_EQ(SyamlalOBrien::check(law.params).why, "");
  const double at = SyamlalOBrien::switches[0].voidFraction;
  const double below = law.evaluate(switchReferenceState(at)).beta;
  const double above = law.evaluate(switchReferenceState(std::nextafter(at, 2.0))).beta;
  EXPECT_NEAR(above / below, 1.0, 1e-9);
  // Off by 5.8 % (D 3.0 for C 0.8): refused, against D.
  law.params.d = 3.0;
  const DragParamsProblem off = SyamlalOBrien::check(law.params);
  EXPECT_EQ(off.key, "d");
  EXPECT_THAT(off.why, ::testing::HasSubstr("Eq. 3.14"));
}

// The list is what byName and names() read: every law once, in the list's order, each name
// choosing the variant's alternative at its place.
TEST(DragLaws, ByNameAndNamesFollowTheList) {
  const auto names = GasSolidsDrag::names();
  ASSERT_EQ(names.size(), std::variant_size_v<DragLaw>);
  for (std::size_t i = 0; i < names.size(); ++i) {
    const GasSolidsDrag drag = GasSolidsDrag::byName(names[i]);
    EXPECT_EQ(drag.name, names[i]);
    EXPECT_EQ(drag.law.index(), i) << names[i];
  }
}

}  // namespace
