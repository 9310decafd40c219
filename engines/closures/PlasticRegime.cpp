#include "engines/closures/PlasticRegime.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"

namespace grainbridge::closures {

std::string PlasticRegime::Params::problem() const {
  // Tested first without a stream: evaluate() asks this of every cell (a stream's construction
  // took 6 % of a binary bed's run time).
  const bool voidFraction = criticalVoidFraction > 0.0 && criticalVoidFraction < 1.0;
  const bool power = coefficient > 0.0 && exponent > 0.0;
  const bool angle = internalFrictionAngle > 0.0 && internalFrictionAngle < 0.5 * M_PI;
  if (voidFraction && power && angle && maxViscosity > 0.0) return {};
  std::ostringstream msg;
  msg.precision(10);
  if (!voidFraction) {
    msg << "the critical void fraction eps_g* must be in (0, 1), got " << criticalVoidFraction;
  } else if (!power) {
    msg << "P* = A (eps_g* - eps_g)^n needs A > 0 and n > 0, got A = " << coefficient << " Pa, n = " << exponent;
  } else if (!angle) {
    msg << "the angle of internal friction must be in (0, 90) degrees, got " << internalFrictionAngle
        << " rad = " << internalFrictionAngle * 180.0 / M_PI << " degree";
    if (internalFrictionAngle >= 0.5 * M_PI && internalFrictionAngle < 90.0)
      msg << " (a bare number is in radians: write \"" << internalFrictionAngle << " degree\" for degrees)";
  } else if (!(maxViscosity > 0.0)) {
    msg << "the largest frictional viscosity must be positive, got " << maxViscosity << " Pa s";
  }
  return msg.str();
}

PlasticRegime::Result PlasticRegime::evaluate(double voidFraction, double solidFraction, double strainInvariant) const {
  return evaluate(voidFraction, solidFraction, strainInvariant, params.criticalVoidFraction);
}

PlasticRegime::Result PlasticRegime::evaluate(double voidFraction, double solidFraction, double strainInvariant,
                                              double criticalVoidFraction) const {
  if (const auto p = params.problem(); !p.empty()) throw Error("plastic regime (Schaeffer): " + p);
  if (!(criticalVoidFraction > 0.0 && criticalVoidFraction < 1.0)) {
    std::ostringstream msg;
    msg << "plastic regime (Schaeffer): the cell's critical void fraction eps_g* must be in (0, 1), got "
        << criticalVoidFraction;
    throw Error(msg.str());
  }
  if (!(voidFraction > 0.0 && voidFraction <= 1.0) || !(solidFraction >= 0.0 && solidFraction < 1.0) ||
      !(strainInvariant >= 0.0 && std::isfinite(strainInvariant))) {
    std::ostringstream msg;
    msg << "plastic regime (Schaeffer): need eps_g in (0, 1], eps_s in [0, 1) and I2D >= 0, got " << voidFraction
        << ", " << solidFraction << ", " << strainInvariant;
    throw Error(msg.str());
  }
  Result r;
  if (voidFraction >= criticalVoidFraction) return r;  // the viscous regime
  r.plastic = true;
  r.pStar = params.coefficient * std::pow(criticalVoidFraction - voidFraction, params.exponent);
  r.pressure = solidFraction * r.pStar;  // Eq. 3.26
  // MFIX's cap on either viscosity; at I2D = 0 the cap is the value (the limit of min(x, cap)).
  if (!(strainInvariant > 0.0)) {
    r.viscosity = params.maxViscosity;
    return r;
  }
  const double shearRate = 2.0 * std::sqrt(strainInvariant);
  double uncapped = 0.0;
  if (params.rheology && r.pressure > 0.0) {
    // mu(I) P^p_s / gamma_dot with gamma_dot = 2 sqrt(I2D) (header).
    r.inertialNumber = params.rheology->inertialNumber(shearRate, r.pressure);
    uncapped = params.rheology->stressRatio(r.inertialNumber) * r.pressure / shearRate;
  } else if (!params.rheology) {
    uncapped = r.pStar * std::sin(params.internalFrictionAngle) / shearRate;
  }
  r.viscosity = std::min(uncapped, params.maxViscosity);
  return r;
}

}  // namespace grainbridge::closures
