#include "engines/closures/ErgunWenYu.hpp"

#include <cmath>

namespace grainbridge::closures {

double ErgunWenYu::dragCoefficient(double re) const {
  return re < kNewtonReynolds ? 24.0 * (1.0 + 0.15 * std::pow(re, 0.687)) / re : params.newtonDragCoefficient;
}

DragCoefficients ErgunWenYu::evaluate(const DragState& s) const {
  validate(s);
  const double epsG = s.voidFraction;
  const double d = s.diameter;
  // Per unit eps_s (see DragState.hpp), so that a lone particle keeps its drag.
  double betaPerSolidFraction = 0.0;
  if (epsG <= kErgunVoidFraction) {
    betaPerSolidFraction = 150.0 * s.solidFraction * s.gasViscosity / (epsG * d * d) + 1.75 * s.gasDensity * s.slip / d;
  } else {
    const double re = d * epsG * s.slip * s.gasDensity / s.gasViscosity;
    // C_D Re |v| stays finite as the slip vanishes: 24 mu_g / (d eps_g rho_g) (Stokes).
    const double cdTimesSlip =
        re > 0.0 ? dragCoefficient(re) * s.slip : 24.0 * s.gasViscosity / (d * epsG * s.gasDensity);
    betaPerSolidFraction = 0.75 * cdTimesSlip * epsG * s.gasDensity / d * std::pow(epsG, params.voidageExponent);
  }
  return dragFromBetaPerSolidFraction(s, betaPerSolidFraction);
}

}  // namespace grainbridge::closures
