#include "engines/closures/Lun1984.hpp"

#include <cmath>
#include <numbers>


namespace grainbridge::closures {

namespace {

// Ma & Ahmadi (1988) as in MFIX gt_pde_lun: a dilute transport coefficient c0 relaxes by gas
// drag before the next collision, c* = c0 / (1 + factor beta c0 / (rho^2 eps^2 g0 theta)), with
// factor 2 for the viscosity and 1.2 for the conductivity. Written as c0 a / (a + factor beta c0)
// so that eps -> 0 or theta -> 0 with beta > 0 gives the limit 0 instead of 0/0 (MFIX sets 0
// below a small theta; it switches to a single-particle drag for very dilute cells, which is the
// caller's business here: beta is an input).
double gasModified(double dilute, double factor, double beta, double rho, double eps, double g0, double theta) {
  if (beta == 0.0) return dilute;
  const double a = rho * rho * eps * eps * g0 * theta;
  if (a == 0.0) return 0.0;
  return dilute * a / (a + factor * beta * dilute);
}

// The same for phase m of a mixture, as MFIX writes it with S = sum_l eps_l g0_ml (calc_mu_s.f,
// 2005): c* = rho eps g0_mm theta c0 / (rho S theta + factor beta c0 / (rho eps)), that is
// c0 (eps g0_mm / S) a / (a + factor beta c0) with a = rho^2 eps S theta. The share eps g0_mm / S
// makes the dilute coefficients additive over identical phases; without gas (beta = 0) it stays,
// as MFIX 21.3's own comment says it should ("the proper extension for M>1 when ro_g=0").
double gasModifiedInMixture(double dilute, double factor, double beta, double rho, double eps, double g0, double sum,
                            double theta) {
  // No solids in the cell: no stress, as MFIX's form gives at eps_m = 0 (its single-particle drag
  // keeps the denominator finite). The granular-gas limit c0 here put the dilute viscosity of a
  // pure granular gas, rho d sqrt(theta) at the neighbours' theta, into empty cells beside a thin
  // phase's faces (FIX26).
  if (!(sum > 0.0)) return 0.0;
  const double share = eps * g0 / sum;
  if (beta == 0.0) return dilute * share;
  const double a = rho * rho * eps * sum * theta;
  if (a == 0.0) return 0.0;
  return dilute * share * a / (a + factor * beta * dilute);
}

}  // namespace

KineticTransport Lun1984::evaluate(const KineticState& s) const {
  validate(s);
  const double sqrtPi = std::sqrt(std::numbers::pi);
  const double eps = s.solidFraction;
  const double theta = s.granularTemperature;
  const double rho = s.density;
  const double d = s.diameter;
  const double e = s.restitution;
  const double beta = s.gasDragCoefficient;
  const double eta = 0.5 * (1.0 + e);  // Lun et al.'s eta
  const bool mixture = s.g0 > 0.0;
  const double g0 = contactG0(s);                         // g0_mm
  const double epsG0 = mixture ? s.contactSum : eps * g0;  // sum_l eps_l g0_ml
  const double dissipationSum = mixture ? s.dissipationSum : epsG0;
  const auto gasReduced = [&](double dilute, double factor) {
    return mixture ? gasModifiedInMixture(dilute, factor, beta, rho, eps, g0, epsG0, theta)
                   : gasModified(dilute, factor, beta, rho, eps, g0, theta);
  };
  const double sqrtTheta = std::sqrt(theta);
  const double rhoDSqrtTheta = rho * d * sqrtTheta;

  KineticTransport out;
  // Kinetic part rho eps theta plus the collisional part 4 eta rho eps^2 g0 theta.
  out.pressure = rho * eps * theta * (1.0 + 4.0 * eta * epsG0);

  // Collisional bulk viscosity; MFIX: eta * Mu_b with Mu_b = 256/(5 pi) mu0 eps^2 g0.
  out.bulkViscosity = 8.0 * eta / (3.0 * sqrtPi) * rhoDSqrtTheta * eps * epsG0;

  const double mu0 = 5.0 * sqrtPi / 96.0 * rhoDSqrtTheta;
  const double muStar = gasReduced(mu0, 2.0);
  out.shearViscosity =
      viscosityFactor() *
      (muStar / (eta * (2.0 - eta) * g0) * (1.0 + 1.6 * eta * epsG0) * (1.0 + 1.6 * eta * (3.0 * eta - 2.0) * epsG0) +
       0.6 * out.bulkViscosity);

  const double kappa0 = 25.0 * sqrtPi / (16.0 * eta * (41.0 - 33.0 * eta)) * rhoDSqrtTheta;
  const double kappaStar = gasReduced(kappa0, 1.2);
  out.conductivity = kappaStar / g0 * (1.0 + 2.4 * eta * epsG0) * (1.0 + 2.4 * eta * eta * (4.0 * eta - 3.0) * epsG0) +
                     4.0 * eta / sqrtPi * rhoDSqrtTheta * eps * epsG0;

  // Eq. 5.7 (Lun et al.'s 48/sqrt(pi) eta (1 - eta) written with e), eps_s^2 g0 read as
  // eps_s sum_l eps_l g0_ll (MFIX source_granular_energy.f): as printed, eps_sm^2 g0_mm would halve
  // the dissipation of two identical halves.
  out.dissipationRate = 12.0 / sqrtPi * (1.0 - e * e) * rho * eps * dissipationSum * theta * sqrtTheta / d;
  return out;
}

}  // namespace grainbridge::closures
