// Lun et al. (1984) + Ma-Ahmadi (engines/closures/Lun1984.hpp). Hand values were computed with
// python3 from Lun's f-function arrangement (collisional viscosity 768/(25 pi) eta eps^2 g0 mu0,
// conductivity term 64/(25 pi)(41 - 33 eta) eta^2 eps^2 g0 kappa0, dissipation
// 48/sqrt(pi) eta (1 - eta) ...), not the code's: the script is quoted in each comment.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engines/closures/Lun1984.hpp"
#include "engines/closures/RadialDistribution.hpp"

using grainbridge::closures::carnahanStarlingG0;
using grainbridge::closures::KineticState;
using grainbridge::closures::KineticTransport;
using grainbridge::closures::Lun1984;
using grainbridge::closures::Lun1984ViscosityForm;

namespace {

const double kSqrtPi = std::sqrt(std::numbers::pi);

void expectRel(double actual, double expected, double rel, const char* what) {
  EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << what;
}

// eps, theta [m^2/s^2], d [m], rho [kg/m^3], e, beta [kg/(m^3 s)]
KineticState state(double eps, double theta, double d, double rho, double e, double beta = 0.0) {
  return KineticState{eps, theta, d, rho, e, beta};
}

// python3, h = (1+e)/2, g = (1-n/2)/(1-n)**3:
//   p  = rho*n*T*(1+4*h*n*g)
//   mu = 5*sqrt(pi)/96*rho*d*sqrt(T) * (1/(h*(2-h)*g)*(1+8/5*h*n*g)*(1+8/5*h*(3*h-2)*n*g)
//                                        + 768/(25*pi)*h*n**2*g)
//   xi = 8*h/(3*sqrt(pi))*rho*d*n**2*g*sqrt(T)
//   k  = 25*sqrt(pi)/(16*h*(41-33*h))*rho*d*sqrt(T) * ((1/g)*(1+12/5*h*n*g)*(1+12/5*h*h*(4*h-3)*n*g)
//                                                       + 64/(25*pi)*(41-33*h)*h*h*n*n*g)
//   J  = 48/sqrt(pi)*h*(1-h)*rho*n*n*g*T**1.5/d
TEST(Lun1984, HandValuesModerateSolidFraction) {
  // n = 0.1, T = 0.01, d = 1e-3, rho = 2500, e = 0.9
  const KineticTransport t = Lun1984{}.evaluate(state(0.1, 0.01, 1e-3, 2500.0, 0.9));
  expectRel(t.pressure, 3.737997256515775, 1e-12, "pressure");
  expectRel(t.shearViscosity, 0.027646350716498284, 1e-12, "shear viscosity");
  expectRel(t.bulkViscosity, 0.004656434377246001, 1e-12, "bulk viscosity");
  expectRel(t.conductivity, 0.09913379836056477, 1e-12, "conductivity");
  expectRel(t.dissipationRate, 41.90790939521404, 1e-12, "dissipation");
}

TEST(Lun1984, HandValuesDense) {
  // n = 0.45, T = 0.05, d = 2.49e-3, rho = 2526, e = 0.97 (Goldschmidt-bed grains)
  const KineticTransport t = Lun1984{}.evaluate(state(0.45, 0.05, 2.49e-3, 2526.0, 0.97));
  expectRel(t.pressure, 526.2297565740045, 1e-12, "pressure");
  expectRel(t.shearViscosity, 1.6781066452064621, 1e-12, "shear viscosity");
  expectRel(t.bulkViscosity, 1.9660129921228275, 1e-12, "bulk viscosity");
  expectRel(t.conductivity, 6.274651869675434, 1e-12, "conductivity");
  expectRel(t.dissipationRate, 4280.765696304607, 1e-12, "dissipation");
}

TEST(Lun1984, MaAhmadiHandValues) {
  // n = 0.2, T = 0.02, d = 2.49e-3, rho = 2526, e = 0.9, beta = 2e4; python3 as above with
  //   mu0* = mu0 / (1 + 2*beta*mu0/(rho**2*n**2*g*T)),  k0* = k0 / (1 + 1.2*beta*k0/(rho**2*n**2*g*T))
  // replacing mu0 and k0 in the first (non-collisional) terms only.
  const KineticTransport gas = Lun1984{}.evaluate(state(0.2, 0.02, 2.49e-3, 2526.0, 0.9, 2.0e4));
  const KineticTransport dry = Lun1984{}.evaluate(state(0.2, 0.02, 2.49e-3, 2526.0, 0.9, 0.0));
  expectRel(gas.shearViscosity, 0.13012908854226649, 1e-12, "gas shear viscosity");
  expectRel(gas.conductivity, 0.3919359279648198, 1e-12, "gas conductivity");
  expectRel(dry.shearViscosity, 0.15813048028315943, 1e-12, "dry shear viscosity");
  expectRel(dry.conductivity, 0.5772625995097114, 1e-12, "dry conductivity");
  // The gas only acts on the dilute (streaming) transport: p, xi and J are unchanged.
  EXPECT_DOUBLE_EQ(gas.pressure, dry.pressure);
  EXPECT_DOUBLE_EQ(gas.bulkViscosity, dry.bulkViscosity);
  EXPECT_DOUBLE_EQ(gas.dissipationRate, dry.dissipationRate);
}

TEST(Lun1984, GasDragReducesViscosityAndConductivityMonotonically) {
  double previousMu = Lun1984{}.evaluate(state(0.05, 0.01, 1e-3, 2500.0, 0.9)).shearViscosity;
  double previousK = Lun1984{}.evaluate(state(0.05, 0.01, 1e-3, 2500.0, 0.9)).conductivity;
  for (const double beta : {1.0, 1e2, 1e4, 1e6}) {
    const KineticTransport t = Lun1984{}.evaluate(state(0.05, 0.01, 1e-3, 2500.0, 0.9, beta));
    EXPECT_LT(t.shearViscosity, previousMu) << "beta = " << beta;
    EXPECT_LT(t.conductivity, previousK) << "beta = " << beta;
    previousMu = t.shearViscosity;
    previousK = t.conductivity;
  }
}

TEST(Lun1984, StrongGasDragLeavesOnlyCollisionalTransport) {
  // beta -> infinity: mu* and k* -> 0, leaving 3/5 xi and 4 eta/sqrt(pi) rho d eps^2 g0 sqrt(T)
  // (python3: 0.05363507380039879 and 0.13408768450099698 at the Ma-Ahmadi state).
  const KineticTransport t = Lun1984{}.evaluate(state(0.2, 0.02, 2.49e-3, 2526.0, 0.9, 1e14));
  expectRel(t.shearViscosity, 0.05363507380039879, 1e-6, "collisional viscosity");
  expectRel(t.conductivity, 0.13408768450099698, 1e-6, "collisional conductivity");
}

TEST(Lun1984, DiluteElasticLimitIsChapmanEnskog) {
  // e = 1, eps -> 0: mu -> 5/96 rho d sqrt(pi theta), k -> 25 sqrt(pi)/128 rho d sqrt(theta)
  // (hard-sphere gas, Chapman & Cowling), p -> rho eps theta (ideal gas).
  const double rho = 2500.0, d = 1e-3, theta = 0.04, eps = 1e-9;
  const KineticTransport t = Lun1984{}.evaluate(state(eps, theta, d, rho, 1.0));
  expectRel(t.shearViscosity, 5.0 / 96.0 * rho * d * std::sqrt(std::numbers::pi * theta), 1e-7, "viscosity");
  expectRel(t.conductivity, 25.0 * kSqrtPi / 128.0 * rho * d * std::sqrt(theta), 1e-7, "conductivity");
  expectRel(t.pressure, rho * eps * theta, 1e-7, "pressure");
}

TEST(Lun1984, DiluteInelasticViscosityCarriesEtaTwoMinusEta) {
  // e = 0.8, eta = 0.9: mu -> 5/96 rho d sqrt(pi theta) / (eta (2 - eta)) = ... / 0.99.
  const double rho = 2500.0, d = 1e-3, theta = 0.04;
  const KineticTransport t = Lun1984{}.evaluate(state(1e-9, theta, d, rho, 0.8));
  expectRel(t.shearViscosity, 5.0 / 96.0 * rho * d * std::sqrt(std::numbers::pi * theta) / 0.99, 1e-7, "viscosity");
}

TEST(Lun1984, NoParticlesNoPressureNoDissipation) {
  const KineticTransport t = Lun1984{}.evaluate(state(0.0, 0.01, 1e-3, 2500.0, 0.9));
  EXPECT_EQ(t.pressure, 0.0);
  EXPECT_EQ(t.bulkViscosity, 0.0);
  EXPECT_EQ(t.dissipationRate, 0.0);
  EXPECT_GT(t.shearViscosity, 0.0);  // the dilute-gas viscosity does not depend on density
  // With gas and no particles the Ma-Ahmadi limit is 0, not 0/0.
  const KineticTransport gas = Lun1984{}.evaluate(state(0.0, 0.01, 1e-3, 2500.0, 0.9, 1e3));
  EXPECT_EQ(gas.shearViscosity, 0.0);
  EXPECT_EQ(gas.conductivity, 0.0);
}

TEST(Lun1984, ZeroTemperatureGivesZeroTransportEvenInGas) {
  for (const double beta : {0.0, 1e3}) {
    const KineticTransport t = Lun1984{}.evaluate(state(0.3, 0.0, 1e-3, 2500.0, 0.9, beta));
    EXPECT_EQ(t.pressure, 0.0);
    EXPECT_EQ(t.shearViscosity, 0.0) << "beta = " << beta;
    EXPECT_EQ(t.bulkViscosity, 0.0);
    EXPECT_EQ(t.conductivity, 0.0) << "beta = " << beta;
    EXPECT_EQ(t.dissipationRate, 0.0);
  }
}

TEST(Lun1984, ElasticCollisionsDoNotDissipate) {
  EXPECT_EQ(Lun1984{}.evaluate(state(0.4, 0.05, 1e-3, 2500.0, 1.0)).dissipationRate, 0.0);
  EXPECT_GT(Lun1984{}.evaluate(state(0.4, 0.05, 1e-3, 2500.0, 0.99)).dissipationRate, 0.0);
}

TEST(Lun1984, DissipationIsEquation57) {
  // Eq. 5.7 written out independently of Lun's eta form.
  const double eps = 0.3, theta = 0.02, d = 2e-3, rho = 1500.0, e = 0.8;
  const double expected =
      12.0 / kSqrtPi * (1.0 - e * e) * rho * eps * eps / d * carnahanStarlingG0(eps) * std::pow(theta, 1.5);
  expectRel(Lun1984{}.evaluate(state(eps, theta, d, rho, e)).dissipationRate, expected, 1e-13, "J");
}

TEST(Lun1984, Name) { EXPECT_EQ(Lun1984{}.name(), "lun1984"); }

}  // namespace

// MFIX's form (calc_mu_s.f: Mu_s = ((2 + ALPHA)/3) (... + 0.6 Mu_b Eta), ALPHA = 1.6): the whole
// shear viscosity, its 3/5 xi included and after the Ma-Ahmadi reduction, 1.2 times the
// published one; nothing else changes, so MFIX's lambda = eta Mu_b - 2/3 mu follows.
TEST(Lun1984, MfixFormMultipliesTheShearViscosityAloneBy1Point2) {
  const Lun1984 mfix{Lun1984ViscosityForm::Mfix};
  EXPECT_EQ(mfix.name(), "lun1984_mfix");
  const KineticTransport dense = mfix.evaluate(state(0.45, 0.05, 2.49e-3, 2526.0, 0.97));
  expectRel(dense.shearViscosity, 1.2 * 1.6781066452064621, 1e-12, "dense shear viscosity");
  expectRel(dense.pressure, 526.2297565740045, 1e-12, "pressure");
  expectRel(dense.bulkViscosity, 1.9660129921228275, 1e-12, "bulk viscosity");
  expectRel(dense.conductivity, 6.274651869675434, 1e-12, "conductivity");
  expectRel(dense.dissipationRate, 4280.765696304607, 1e-12, "dissipation");
  expectRel(dense.secondViscosity(), 1.9660129921228275 - 2.0 / 3.0 * 1.2 * 1.6781066452064621, 1e-12, "lambda");
  const KineticTransport gas = mfix.evaluate(state(0.2, 0.02, 2.49e-3, 2526.0, 0.9, 2.0e4));
  expectRel(gas.shearViscosity, 1.2 * 0.13012908854226649, 1e-12, "gas shear viscosity");
}
