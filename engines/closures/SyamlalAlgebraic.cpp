#include "engines/closures/SyamlalAlgebraic.hpp"

#include <cmath>
#include <numbers>


namespace grainbridge::closures {

std::string_view SyamlalAlgebraic::name() const {
  return params.viscosityForm == SyamlalViscosityForm::Printed ? "syamlal_algebraic" : "syamlal_algebraic_mfix";
}

SyamlalCoefficients SyamlalAlgebraic::coefficients(const KineticState& s) const {
  validate(s);
  const double sqrtPi = std::sqrt(std::numbers::pi);
  const double e = s.restitution;
  const double rho = s.density;
  const double d = s.diameter;
  const double g0 = contactG0(s);
  const double epsG0 = s.solidFraction * g0;
  // The only difference between the two forms (see the header).
  const double leading = params.viscosityForm == SyamlalViscosityForm::Printed ? 1.0 : 0.5 * (3.0 * e + 1.0);

  SyamlalCoefficients k;
  k.k1 = 2.0 * (1.0 + e) * rho * g0;  // Eq. 3.23
  k.k3 = 0.5 * d * rho *
         (sqrtPi / (3.0 * (3.0 - e)) * (leading + 0.4 * (1.0 + e) * (3.0 * e - 1.0) * epsG0) +
          8.0 * epsG0 * (1.0 + e) / (5.0 * sqrtPi));                             // Eq. 3.25
  k.k2 = 4.0 * d * rho * (1.0 + e) * epsG0 / (3.0 * sqrtPi) - 2.0 / 3.0 * k.k3;  // Eq. 3.24
  k.k4 = 12.0 * (1.0 - e * e) * rho * g0 / (sqrtPi * d);                         // Eq. 5.7
  return k;
}

KineticTransport SyamlalAlgebraic::evaluate(const KineticState& s) const {
  const SyamlalCoefficients k = coefficients(s);
  const double sqrtPi = std::sqrt(std::numbers::pi);
  const double eps = s.solidFraction;
  const double theta = s.granularTemperature;
  const double sqrtTheta = std::sqrt(theta);
  const double e = s.restitution;
  const double epsG0 = eps * contactG0(s);

  KineticTransport out;
  out.pressure = k.k1 * eps * eps * theta;  // Eq. 3.21
  out.shearViscosity = k.k3 * eps * sqrtTheta;
  // Eq. 3.22's lambda = K2 eps sqrt(theta) = xi - 2/3 mu, so xi is the first term of Eq. 3.24.
  // Taken directly rather than as (K2 + 2/3 K3) eps sqrt(theta), which cancels at low eps and
  // would make xi depend (in the last digits) on the viscosity form.
  out.bulkViscosity = 4.0 * s.diameter * s.density * (1.0 + e) * epsG0 / (3.0 * sqrtPi) * eps * sqrtTheta;
  out.dissipationRate = k.k4 * eps * eps * theta * sqrtTheta;  // gamma = K4 eps^2 theta^1.5

  // Syamlal, Rogers & O'Brien (1993) conductivity, eta = (1 + e)/2 (see the header).
  const double eta = 0.5 * (1.0 + e);
  out.conductivity = 15.0 * s.diameter * s.density * eps * sqrtPi * sqrtTheta / (4.0 * (41.0 - 33.0 * eta)) *
                     (1.0 + 2.4 * eta * eta * (4.0 * eta - 3.0) * epsG0 +
                      16.0 / (15.0 * std::numbers::pi) * (41.0 - 33.0 * eta) * eta * epsG0);
  return out;
}

}  // namespace grainbridge::closures
