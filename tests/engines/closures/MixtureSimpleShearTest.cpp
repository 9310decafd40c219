// Steady simple shear of a mixture under the multi-fluid model's kinetic theory (issue 60): each
// phase's temperature from its own shear work against its own dissipation, checked against a hand
// evaluation of Lebowitz's g0 and Lun et al.'s closures at one binary state, and against the one
// phase that two identical halves make under the summed form (and do not under the printed one).
#include "engines/closures/MixtureSimpleShear.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/Error.hpp"

using namespace grainbridge;
using namespace grainbridge::closures;

namespace {

constexpr double kShearRate = 100.0;

// Lun et al. (1984) at theta = 1 with Ma-Ahmadi's gas term absent, sums S = sum_l eps_l g0_ml and
// D = sum_l eps_l g0_ll (MFiX's SUM_EpsGo): shear viscosity, dissipation and pressure coefficient.
// The dilute viscosity mu0 takes the phase's share eps g0_mm / S of it, as MFiX's calc_mu_s.f
// writes the mixture (1 under the printed form, where S = eps g0_mm).
struct Hand {
  double mu, J, p;
};
Hand lunAtUnitTemperature(double eps, double d, double rho, double e, double g0, double S, double D) {
  const double pi = std::numbers::pi, eta = 0.5 * (1.0 + e);
  const double muB = 8.0 * eta / (3.0 * std::sqrt(pi)) * rho * d * eps * S;
  const double mu0 = 5.0 * std::sqrt(pi) / 96.0 * rho * d * (eps * g0 / S);
  const double mu =
      mu0 / (eta * (2.0 - eta) * g0) * (1.0 + 1.6 * eta * S) * (1.0 + 1.6 * eta * (3.0 * eta - 2.0) * S) + 0.6 * muB;
  const double J = 12.0 / std::sqrt(pi) * (1.0 - e * e) * rho * eps * D / d;
  return {mu, J, rho * eps * (1.0 + 4.0 * eta * S)};
}

// Lebowitz (1964) as MFiX writes it: g0_lm = 1/eps_g + 3 d_l d_m / (eps_g^2 (d_l + d_m)) sum_k eps_k / d_k.
double lebowitz(double epsS, double epsL, double dS, double dL, double dl, double dm) {
  const double epsG = 1.0 - epsS - epsL;
  return 1.0 / epsG + 3.0 * dl * dm / (epsG * epsG * (dl + dm)) * (epsS / dS + epsL / dL);
}

}  // namespace

TEST(MixtureSimpleShear, TheGoldschmidtPairMatchesAHandEvaluation) {
  const double dS = 1.52e-3, dL = 2.49e-3, rhoS = 2523.0, rhoL = 2526.0, e = 0.9, epsS = 0.12, epsL = 0.08;
  const std::vector<ShearedPhase> pair{{epsS, dS, rhoS, e}, {epsL, dL, rhoL, e}};
  const double gSS = lebowitz(epsS, epsL, dS, dL, dS, dS), gLL = lebowitz(epsS, epsL, dS, dL, dL, dL),
               gSL = lebowitz(epsS, epsL, dS, dL, dS, dL);
  for (const auto form : {MixtureKineticTheory::Summed, MixtureKineticTheory::PerPhase}) {
    const bool summed = form == MixtureKineticTheory::Summed;
    const auto got = mixtureSimpleShear(KineticModelName::Lun1984, form, pair, kShearRate);
    ASSERT_EQ(got.size(), 2u);
    const double D = epsS * gSS + epsL * gLL;
    const Hand small = lunAtUnitTemperature(epsS, dS, rhoS, e, gSS, summed ? epsS * gSS + epsL * gSL : epsS * gSS,
                                            summed ? D : epsS * gSS);
    const Hand large = lunAtUnitTemperature(epsL, dL, rhoL, e, gLL, summed ? epsS * gSL + epsL * gLL : epsL * gLL,
                                            summed ? D : epsL * gLL);
    for (std::size_t m = 0; m < 2; ++m) {
      const Hand& h = m == 0 ? small : large;
      const double theta = h.mu * kShearRate * kShearRate / h.J;
      const double rho = m == 0 ? rhoS : rhoL, eps = m == 0 ? epsS : epsL;
      EXPECT_NEAR(got[m].granularTemperature, theta, 1e-12 * theta) << m << summed;
      EXPECT_NEAR(got[m].pressure, h.p * theta, 1e-12 * h.p * theta);
      EXPECT_NEAR(got[m].kineticPressure, rho * eps * theta, 1e-12 * rho * eps * theta);
      EXPECT_NEAR(got[m].shearStress, h.mu * std::sqrt(theta) * kShearRate, 1e-12 * got[m].shearStress);
      // In steady homogeneous shear each phase's shear work is its dissipation.
      EXPECT_NEAR(got[m].shearStress * kShearRate, got[m].dissipationRate, 1e-12 * got[m].dissipationRate);
    }
  }
}

TEST(MixtureSimpleShear, TwoIdenticalHalvesAreTheOnePhaseOnlyUnderTheSummedForm) {
  const ShearedPhase whole{0.3, 1e-3, 2500.0, 0.9}, half{0.15, 1e-3, 2500.0, 0.9};
  const auto one = mixtureSimpleShear(KineticModelName::Lun1984, MixtureKineticTheory::Summed, {whole}, kShearRate);
  const auto summed =
      mixtureSimpleShear(KineticModelName::Lun1984, MixtureKineticTheory::Summed, {half, half}, kShearRate);
  const auto printed =
      mixtureSimpleShear(KineticModelName::Lun1984, MixtureKineticTheory::PerPhase, {half, half}, kShearRate);
  for (std::size_t m = 0; m < 2; ++m) {
    EXPECT_NEAR(summed[m].granularTemperature, one[0].granularTemperature, 1e-12 * one[0].granularTemperature);
    EXPECT_NEAR(2.0 * summed[m].pressure, one[0].pressure, 1e-12 * one[0].pressure);
    EXPECT_NEAR(2.0 * summed[m].dissipationRate, one[0].dissipationRate, 1e-12 * one[0].dissipationRate);
    // Colliding with its own kind only, each half dissipates less at a given theta and runs hotter.
    EXPECT_GT(printed[m].granularTemperature, 1.2 * one[0].granularTemperature);
  }
}

TEST(MixtureSimpleShear, TheRotationModelScalesTheDissipationAndSoTheTemperature) {
  // theta = mu(1) gammadot^2 / (s J(1)): a dissipation scale s divides theta by s, and the shear
  // work still equals the (scaled) dissipation.
  ShearedPhase plain{0.2, 1e-3, 2500.0, 0.9}, rotating = plain;
  rotating.dissipationScale = 1.6;
  const auto a = mixtureSimpleShear(KineticModelName::Lun1984, MixtureKineticTheory::Summed, {plain}, kShearRate);
  const auto b = mixtureSimpleShear(KineticModelName::Lun1984, MixtureKineticTheory::Summed, {rotating}, kShearRate);
  EXPECT_NEAR(b[0].granularTemperature, a[0].granularTemperature / 1.6, 1e-12 * a[0].granularTemperature);
  EXPECT_NEAR(b[0].shearStress * kShearRate, b[0].dissipationRate, 1e-12 * b[0].dissipationRate);
}

TEST(MixtureSimpleShear, RefusesNoPhaseAndAModelThatDoesNotScaleWithTheta) {
  EXPECT_THROW((void)mixtureSimpleShear(KineticModelName::Lun1984, MixtureKineticTheory::Summed, {}, kShearRate),
               Error);
  // Syamlal's algebraic form has the same theta scaling; what it must refuse is an invalid state.
  EXPECT_THROW((void)mixtureSimpleShear(KineticModelName::Lun1984, MixtureKineticTheory::Summed,
                                        {{0.3, -1e-3, 2500.0, 0.9}}, kShearRate),
               Error);
}
