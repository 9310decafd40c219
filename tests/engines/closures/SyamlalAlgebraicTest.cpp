// Printed Eqs. 3.21-3.25 and MFIX's variant (engines/closures/SyamlalAlgebraic.hpp). Hand
// values: python3 with g = (1-n/2)/(1-n)**3 and the viscosity split into the kinetic and
// collisional parts (a different arrangement from K3):
//   p   = 2*(1+e)*rho*g*n*n*T
//   mu  = n*d*rho*sqrt(pi*T)/(6*(3-e))*(L + 0.4*(1+e)*(3*e-1)*n*g) + 0.8*n*n*rho*d*g*(1+e)*sqrt(T/pi)
//         with L = 1 (Printed) or (3*e+1)/2 (Mfix)
//   xi  = 4*d*rho*(1+e)*n*n*g*sqrt(T)/(3*sqrt(pi))
//   k   = rho*d*sqrt(T)*(2*n*n*g*(1+e)/sqrt(pi) + 9/8*sqrt(pi)*g*0.25*(1+e)**2*(2*e-1)*n*n/(49/16-33*e/16)
//                        + 15/32*sqrt(pi)*n/(49/16-33*e/16))      (OpenFOAM's arrangement)
//   J   = 12*(1-e*e)*rho*g*n*n*T**1.5/(d*sqrt(pi))
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engines/closures/SyamlalAlgebraic.hpp"

using grainbridge::closures::KineticState;
using grainbridge::closures::KineticTransport;
using grainbridge::closures::SyamlalAlgebraic;
using grainbridge::closures::SyamlalCoefficients;
using grainbridge::closures::SyamlalViscosityForm;

namespace {

void expectRel(double actual, double expected, double rel, const char* what) {
  EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << what;
}

SyamlalAlgebraic model(SyamlalViscosityForm form) {
  SyamlalAlgebraic m;
  m.params.viscosityForm = form;
  return m;
}

const SyamlalAlgebraic kPrinted = model(SyamlalViscosityForm::Printed);
const SyamlalAlgebraic kMfix = model(SyamlalViscosityForm::Mfix);

TEST(SyamlalAlgebraic, HandValuesModerateSolidFraction) {
  // n = 0.1, T = 0.01, d = 1e-3, rho = 2500, e = 0.9
  const KineticState s{0.1, 0.01, 1e-3, 2500.0, 0.9, 0.0};
  const KineticTransport p = kPrinted.evaluate(s);
  expectRel(p.pressure, 1.237997256515775, 1e-12, "pressure");
  expectRel(p.shearViscosity, 0.00690274495084698, 1e-12, "printed shear viscosity");
  expectRel(p.bulkViscosity, 0.004656434377246001, 1e-12, "bulk viscosity");
  expectRel(p.conductivity, 0.02809241932785198, 1e-12, "conductivity");
  expectRel(p.dissipationRate, 41.90790939521399, 1e-12, "dissipation");
  expectRel(kMfix.evaluate(s).shearViscosity, 0.009892002437493188, 1e-12, "mfix shear viscosity");
}

TEST(SyamlalAlgebraic, HandValuesDense) {
  // n = 0.45, T = 0.05, d = 2.49e-3, rho = 2526, e = 0.97
  const KineticState s{0.45, 0.05, 2.49e-3, 2526.0, 0.97, 0.0};
  const KineticTransport p = kPrinted.evaluate(s);
  expectRel(p.pressure, 469.3947565740045, 1e-12, "pressure");
  expectRel(p.shearViscosity, 1.5622726131011504, 1e-12, "printed shear viscosity");
  expectRel(p.bulkViscosity, 1.9660129921228275, 1e-12, "bulk viscosity");
  expectRel(p.conductivity, 5.716223408935244, 1e-12, "conductivity");
  expectRel(p.dissipationRate, 4280.7656963046065, 1e-12, "dissipation");
  expectRel(kMfix.evaluate(s).shearViscosity, 1.650227754047652, 1e-12, "mfix shear viscosity");
}

TEST(SyamlalAlgebraic, CoefficientsAndSecondViscosity) {
  // Eqs. 3.23-3.25 and K4 at n = 0.1, e = 0.9, d = 1e-3, rho = 2500 (python3, printed form):
  //   K1 = 2*(1+e)*rho*g, K3 = d*rho/2*(sqrt(pi)/(3*(3-e))*(1+0.4*(1+e)*(3*e-1)*n*g) + 8*n*g*(1+e)/(5*sqrt(pi))),
  //   K2 = 4*d*rho*(1+e)*n*g/(3*sqrt(pi)) - 2/3*K3, K4 = 12*(1-e*e)*rho*g/(d*sqrt(pi))
  const KineticState s{0.1, 0.01, 1e-3, 2500.0, 0.9, 0.0};
  const SyamlalCoefficients k = kPrinted.coefficients(s);
  expectRel(k.k1, 12379.97256515775, 1e-12, "K1");
  expectRel(k.k2, 0.005460441001468086, 1e-11, "K2");
  expectRel(k.k3, 0.6902744950846978, 1e-12, "K3");
  expectRel(k.k4, 4190790.9395213984, 1e-12, "K4");
  // Eq. 3.22: lambda = K2 eps sqrt(theta) = 5.460441001468086e-05.
  expectRel(kPrinted.evaluate(s).secondViscosity(), 5.460441001468086e-05, 1e-10, "lambda");
}

TEST(SyamlalAlgebraic, VariantsDifferOnlyInTheKineticViscosityTerm) {
  const double d = 2e-3, rho = 2000.0, theta = 0.03;
  for (const double e : {0.5, 0.8, 0.9, 1.0}) {
    for (const double eps : {0.02, 0.2, 0.5}) {
      const KineticState s{eps, theta, d, rho, e, 0.0};
      const KineticTransport p = kPrinted.evaluate(s);
      const KineticTransport m = kMfix.evaluate(s);
      EXPECT_DOUBLE_EQ(m.pressure, p.pressure);
      EXPECT_DOUBLE_EQ(m.bulkViscosity, p.bulkViscosity);
      EXPECT_DOUBLE_EQ(m.conductivity, p.conductivity);
      EXPECT_DOUBLE_EQ(m.dissipationRate, p.dissipationRate);
      // ((3e+1)/2 - 1) * d rho/2 * sqrt(pi)/(3 (3-e)) * eps sqrt(theta)
      const double difference =
          std::sqrt(std::numbers::pi) * (3.0 * e - 1.0) / (12.0 * (3.0 - e)) * rho * d * eps * std::sqrt(theta);
      expectRel(m.shearViscosity - p.shearViscosity, difference, 1e-9, "mu_Mfix - mu_Printed");
    }
  }
}

TEST(SyamlalAlgebraic, VariantsCoincideOnlyWhereLeadingTermsAgree) {
  // (3e+1)/2 = 1 at e = 1/3; at e = 1 the Mfix kinetic term is twice the printed one.
  const KineticState third{0.3, 0.02, 1e-3, 2500.0, 1.0 / 3.0, 0.0};
  expectRel(kMfix.evaluate(third).shearViscosity, kPrinted.evaluate(third).shearViscosity, 1e-14, "e = 1/3");
  const KineticState elastic{0.3, 0.02, 1e-3, 2500.0, 1.0, 0.0};
  EXPECT_GT(kMfix.evaluate(elastic).shearViscosity, kPrinted.evaluate(elastic).shearViscosity);
}

TEST(SyamlalAlgebraic, NoKineticPressureAndViscosityVanishWithoutParticles) {
  // Eq. 3.21 is purely collisional: p ~ eps^2, so p/eps -> 0, unlike Lun's rho theta.
  const KineticTransport t = kPrinted.evaluate(KineticState{0.0, 0.01, 1e-3, 2500.0, 0.9, 0.0});
  EXPECT_EQ(t.pressure, 0.0);
  EXPECT_EQ(t.shearViscosity, 0.0);
  EXPECT_EQ(t.conductivity, 0.0);
  const KineticTransport dilute = kPrinted.evaluate(KineticState{1e-6, 0.01, 1e-3, 2500.0, 0.9, 0.0});
  EXPECT_LT(dilute.pressure / (1e-6 * 2500.0 * 0.01), 1e-5);
}

TEST(SyamlalAlgebraic, ElasticCollisionsDoNotDissipate) {
  EXPECT_EQ(kPrinted.evaluate(KineticState{0.4, 0.05, 1e-3, 2500.0, 1.0, 0.0}).dissipationRate, 0.0);
  EXPECT_EQ(kPrinted.coefficients(KineticState{0.4, 0.05, 1e-3, 2500.0, 1.0, 0.0}).k4, 0.0);
}

TEST(SyamlalAlgebraic, IgnoresGasDrag) {
  const KineticState dry{0.2, 0.02, 1e-3, 2500.0, 0.9, 0.0};
  KineticState gas = dry;
  gas.gasDragCoefficient = 1e4;
  EXPECT_DOUBLE_EQ(kPrinted.evaluate(gas).shearViscosity, kPrinted.evaluate(dry).shearViscosity);
  EXPECT_DOUBLE_EQ(kPrinted.evaluate(gas).conductivity, kPrinted.evaluate(dry).conductivity);
}

TEST(SyamlalAlgebraic, NamesAndDefault) {
  EXPECT_EQ(SyamlalAlgebraic{}.params.viscosityForm, SyamlalViscosityForm::Printed);
  EXPECT_EQ(kPrinted.name(), "syamlal_algebraic");
  EXPECT_EQ(kMfix.name(), "syamlal_algebraic_mfix");
}

}  // namespace
