// Gas-solids drag laws (engines/closures: SyamlalOBrien, ErgunWenYu, GasSolidsDrag) against
// values computed outside our code (python3, the reference's figures, VALIDATION.md): the
// Eq. 3.14 residuals of Table 4.3, the minimum fluidization velocities each law implies, the
// per-particle form of Eq. 7.29, the zero-slip and lone-particle limits, and where each law is
// continuous and where it jumps by construction.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/Error.hpp"
#include "engines/closures/GasSolidsDrag.hpp"

using namespace grainbridge;
using namespace grainbridge::closures;

namespace {

// Air as VALIDATION.md takes it (the reference gives no gas properties).
constexpr double kRhoG = 1.2;
constexpr double kMuG = 1.8e-5;
constexpr double kG = 9.81;

DragState state(double epsG, double epsS, double d, double slip) { return {epsG, epsS, d, kRhoG, kMuG, slip}; }

// Superficial gas velocity U at which the drag on a bed at rest at void fraction epsG carries its
// buoyant weight. Gas and solids momentum at rest (Eqs. 3.3-3.4, no solids stress) give
// beta U / eps_g = eps_s eps_g (rho_s - rho_g) g, with slip U / eps_g. Bisection on U.
double minimumFluidization(const GasSolidsDrag& law, double d, double rhoS, double epsG = 0.417) {
  const double epsS = 1.0 - epsG;
  double lo = 1e-6, hi = 20.0;
  for (int i = 0; i < 200; ++i) {
    const double u = 0.5 * (lo + hi);
    const double excess =
        law.evaluate(state(epsG, epsS, d, u / epsG)).beta * u / epsG - epsS * epsG * (rhoS - kRhoG) * kG;
    (excess > 0.0 ? hi : lo) = u;
  }
  return 0.5 * (lo + hi);
}

TEST(SyamlalOBrien, Table43SetsMissTheContinuityConditionAsVALIDATIONSays) {
  // (C 0.85^1.28 - 0.85^D) / 0.85^D in %: -0.049, -0.562, +0.064 (python3).
  const struct { double c, d, residualPercent; } sets[] = {{0.8, 2.65, -0.05}, {0.7, 3.44, -0.56}, {0.64, 4.03, 0.06}};
  for (const auto& s : sets) {
    const SyamlalOBrien::Params p{s.c, s.d};
    EXPECT_NEAR(100.0 * p.continuityResidual(), s.residualPercent, 0.005) << s.c << ", " << s.d;
    EXPECT_EQ(p.continuityProblem(), "") << s.c << ", " << s.d;
  }
  const SyamlalOBrien::Params off{0.8, 3.0};  // 5.8 % off
  EXPECT_THAT(off.continuityProblem(), ::testing::HasSubstr("Eq. 3.14"));
  EXPECT_THAT(off.continuityProblem(), ::testing::HasSubstr("D = 2.653 satisfies it"));
}

TEST(GasSolidsDrag, MinimumFluidizationVelocitiesOfEachLaw) {
  // Goldschmidt's glass beads (2526 kg/m3) and Tsuji's 4 mm, 2.7 g/cm3 particles at eps 0.417;
  // figures of issue 15 / VALIDATION.md (the reference quotes U_mf 1.28, 0.92 and 1.80 m/s).
  const auto so = GasSolidsDrag::byName("syamlal_obrien");
  const auto ergun = GasSolidsDrag::byName("ergun_wen_yu");
  EXPECT_NEAR(minimumFluidization(so, 2.49e-3, 2526.0), 1.206, 0.005 * 1.206);
  EXPECT_NEAR(minimumFluidization(so, 1.52e-3, 2526.0), 0.867, 0.005 * 0.867);
  EXPECT_NEAR(minimumFluidization(ergun, 2.49e-3, 2526.0), 1.317, 0.005 * 1.317);
  EXPECT_NEAR(minimumFluidization(ergun, 1.52e-3, 2526.0), 0.920, 0.005 * 0.920);
  EXPECT_NEAR(minimumFluidization(ergun, 4.0e-3, 2700.0), 1.821, 0.005 * 1.821);
  // Below eps_g 0.8 the Gidaspow variant is the same Ergun law.
  EXPECT_DOUBLE_EQ(minimumFluidization(GasSolidsDrag::byName("gidaspow"), 4.0e-3, 2700.0),
                   minimumFluidization(ergun, 4.0e-3, 2700.0));
}

TEST(GasSolidsDrag, PerParticleFormSumsBackToBeta) {
  // Eqs. 7.32-7.33: eps_g f_d summed over the n = eps_s / (pi d^3 / 6) particles of unit volume.
  for (const auto& name : GasSolidsDrag::names()) {
    const auto law = GasSolidsDrag::byName(name);
    for (const double epsG : {0.45, 0.79, 0.81, 0.9, 0.99}) {
      const DragState s = state(epsG, 1.0 - epsG, 2.5e-3, 0.7);
      const auto c = law.evaluate(s);
      const double particlesPerVolume = s.solidFraction / (M_PI / 6.0 * std::pow(s.diameter, 3));
      EXPECT_NEAR(epsG * c.particle * particlesPerVolume, c.beta, 1e-12 * c.beta) << name << " eps_g " << epsG;
    }
  }
}

TEST(GasSolidsDrag, ALoneParticleFeelsTheSingleSphereDrag) {
  // eps_s -> 0, eps_g = 1: beta vanishes, the particle keeps 1/2 C_D rho_g (pi d^2 / 4) |v| for
  // the Wen-Yu branch (eps_g^n = 1).
  const double d = 2.5e-3, slip = 1.5;
  const auto law = GasSolidsDrag::byName("ergun_wen_yu");
  const auto c = law.evaluate(state(1.0, 0.0, d, slip));
  EXPECT_EQ(c.beta, 0.0);
  const double re = d * slip * kRhoG / kMuG;  // 250
  const double cd = 24.0 * (1.0 + 0.15 * std::pow(re, 0.687)) / re;
  EXPECT_NEAR(c.particle, 0.5 * cd * kRhoG * M_PI * d * d / 4.0 * slip, 1e-12 * c.particle);
  EXPECT_GT(GasSolidsDrag::byName("syamlal_obrien").evaluate(state(1.0, 0.0, d, slip)).particle, 0.0);
}

TEST(GasSolidsDrag, ZeroSlipGivesTheFiniteStokesLimit) {
  const double d = 2.0e-3;
  // Syamlal-O'Brien at Re = 0: V_r = A = eps_g^4.14, C_DS Re -> 4.8^2 V_r.
  const double epsG = 0.6, epsS = 0.4;
  const double a = std::pow(epsG, 4.14);
  EXPECT_NEAR(GasSolidsDrag::byName("syamlal_obrien").evaluate(state(epsG, epsS, d, 0.0)).beta,
              3.0 * 23.04 * epsS * epsG * kMuG / (4.0 * a * d * d), 1e-9);
  // Continuous into it, though not smooth: beta grows like sqrt(Re) at first (0.9 % at 1 um/s).
  const double at0 = GasSolidsDrag::byName("syamlal_obrien").evaluate(state(epsG, epsS, d, 0.0)).beta;
  const double near0 = GasSolidsDrag::byName("syamlal_obrien").evaluate(state(epsG, epsS, d, 1e-10)).beta;
  EXPECT_NEAR(near0, at0, 1e-3 * at0);
  // Wen-Yu at Re = 0: 3/4 (24 mu / (d eps_g rho_g)) eps_g eps_s rho_g / d eps_g^-2.7.
  const double dilute = 0.9;
  EXPECT_NEAR(GasSolidsDrag::byName("ergun_wen_yu").evaluate(state(dilute, 0.1, d, 0.0)).beta,
              18.0 * kMuG * 0.1 / (d * d) * std::pow(dilute, -2.7), 1e-9);
  const double wy0 = GasSolidsDrag::byName("ergun_wen_yu").evaluate(state(dilute, 0.1, d, 0.0)).beta;
  const double wyNear0 = GasSolidsDrag::byName("ergun_wen_yu").evaluate(state(dilute, 0.1, d, 1e-6)).beta;
  EXPECT_NEAR(wyNear0, wy0, 1e-3 * wy0);
  // Ergun at zero slip: the viscous term alone.
  EXPECT_DOUBLE_EQ(GasSolidsDrag::byName("ergun_wen_yu").evaluate(state(epsG, epsS, d, 0.0)).beta,
                   150.0 * epsS * epsS * kMuG / (epsG * d * d));
}

TEST(SyamlalOBrien, IsContinuousAtTheSwitchOfEq313WhenEq314Holds) {
  SyamlalOBrien law;
  law.params = {0.8, std::log(0.8 * std::pow(0.85, 1.28)) / std::log(0.85)};  // Eq. 3.14 exactly
  const double below = law.evaluate(state(0.85, 0.15, 2.5e-3, 1.0)).beta;
  const double above = law.evaluate(state(std::nextafter(0.85, 1.0), 0.15, 2.5e-3, 1.0)).beta;
  EXPECT_NEAR(above, below, 1e-9 * below);
  // Table 4.3's first set (0.05 % off) jumps by less than 0.1 %.
  law.params = {0.8, 2.65};
  const double b1 = law.evaluate(state(0.85, 0.15, 2.5e-3, 1.0)).beta;
  const double b2 = law.evaluate(state(std::nextafter(0.85, 1.0), 0.15, 2.5e-3, 1.0)).beta;
  EXPECT_LT(std::abs(b2 / b1 - 1.0), 1e-3);
}

TEST(ErgunWenYu, JumpsWhereItIsDocumentedTo) {
  const auto law = ErgunWenYu::asPrinted();
  // Eq. 7.31 at Re = 1000: the Schiller-Naumann branch gives 0.43829, the Newton branch 0.43.
  EXPECT_NEAR(law.dragCoefficient(std::nextafter(1000.0, 0.0)), 0.438288, 1e-6);
  EXPECT_DOUBLE_EQ(law.dragCoefficient(1000.0), 0.43);
  EXPECT_DOUBLE_EQ(ErgunWenYu::gidaspow().dragCoefficient(1000.0), 0.44);
  // Eq. 7.30 at eps_g = 0.8: Ergun below, Wen-Yu above; at 2.5 mm and 1 m/s they differ by
  // tens of percent (python3: 189.6 against 100.8 kg/(m^3 s)).
  const double ergun = law.evaluate(state(0.8, 0.2, 2.5e-3, 1.0)).beta;
  const double wenYu = law.evaluate(state(std::nextafter(0.8, 1.0), 0.2, 2.5e-3, 1.0)).beta;
  EXPECT_NEAR(ergun, 150.0 * 0.04 * kMuG / (0.8 * 2.5e-3 * 2.5e-3) + 1.75 * 0.2 * kRhoG / 2.5e-3, 1e-9);
  EXPECT_GT(std::abs(wenYu / ergun - 1.0), 0.2);
  // Gidaspow's exponent -2.65 against the printed -2.7: (0.9)^0.05 apart at equal C_D.
  const auto printed = law.evaluate(state(0.9, 0.1, 2.5e-3, 1.0)).beta;
  const auto gidaspow = ErgunWenYu::gidaspow().evaluate(state(0.9, 0.1, 2.5e-3, 1.0)).beta;
  EXPECT_NEAR(gidaspow / printed, std::pow(0.9, 0.05), 1e-12);
}

TEST(GasSolidsDrag, RefusesBadStatesAndUnknownNames) {
  const auto law = GasSolidsDrag::byName("syamlal_obrien");
  EXPECT_THROW((void)law.evaluate(state(0.0, 0.5, 1e-3, 1.0)), Error);
  EXPECT_THROW((void)law.evaluate(state(0.5, 0.5, -1e-3, 1.0)), Error);
  EXPECT_THROW((void)law.evaluate(state(0.5, 0.5, 1e-3, std::numeric_limits<double>::quiet_NaN())), Error);
  try {
    (void)GasSolidsDrag::byName("wen_yu");
    FAIL() << "an unknown law must be refused";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("known: syamlal_obrien, ergun_wen_yu, gidaspow"));
  }
}

}  // namespace

namespace {

// The Stokes number quoted for the Goldschmidt bed (about 37,000 for 2.5 mm glass at 1.92 m/s,
// line ~1931) is the Stokes relaxation time rho_s d^2 / (18 mu_g) over d / U: it implies
// mu_g = 1.8e-5 Pa s, the gas viscosity VALIDATION.md takes (the reference gives none).
TEST(GasSolidsDrag, StokesNumberQuotedForTheGoldschmidtBedImpliesTheGasViscosity) {
  const double stokes = 2526.0 * 2.5e-3 * 1.92 / (18.0 * kMuG);
  EXPECT_NEAR(stokes, 37000.0, 0.02 * 37000.0);
}

}  // namespace
