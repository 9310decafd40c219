#include "engines/closures/SyamlalOBrien.hpp"

#include <cmath>
#include <sstream>

namespace grainbridge::closures {

double SyamlalOBrien::Params::continuityResidual() const {
  const double right = std::pow(0.85, d);
  return (c * std::pow(0.85, 1.28) - right) / right;
}

std::string SyamlalOBrien::Params::continuityProblem() const {
  const double r = continuityResidual();
  if (std::abs(r) <= kContinuityTolerance) return {};
  std::ostringstream msg;
  msg.precision(4);
  msg << "C = " << c << " and D = " << d << " miss the continuity condition C 0.85^1.28 = 0.85^D (Eq. 3.14) by "
      << 100.0 * r << " %, more than " << 100.0 * kContinuityTolerance << " %: B of Eq. 3.13 would jump at eps_g 0.85; "
      << "D = " << std::log(c * std::pow(0.85, 1.28)) / std::log(0.85) << " satisfies it for this C";
  return msg.str();
}

DragCoefficients SyamlalOBrien::evaluate(const DragState& s) const {
  validate(s);
  const double epsG = s.voidFraction;
  const double re = s.diameter * s.slip * s.gasDensity / s.gasViscosity;                       // Eq. 3.15
  const double a = std::pow(epsG, 4.14);                                                       // Eq. 3.12
  const double b = epsG <= 0.85 ? params.c * std::pow(epsG, 1.28) : std::pow(epsG, params.d);  // Eq. 3.13
  const double vr =
      0.5 * (a - 0.06 * re + std::sqrt(0.0036 * re * re + 0.12 * re * (2.0 * b - a) + a * a));  // Eq. 3.11
  // Eqs. 3.10 and 3.16 multiplied out (C_DS Re = (0.63 sqrt(Re) + 4.8 sqrt(V_r))^2), per unit eps_s.
  const double root = 0.63 * std::sqrt(re) + 4.8 * std::sqrt(vr);
  const double betaPerSolidFraction =
      3.0 * epsG * s.gasViscosity * root * root / (4.0 * vr * vr * s.diameter * s.diameter);
  return dragFromBetaPerSolidFraction(s, betaPerSolidFraction);
}

}  // namespace grainbridge::closures
