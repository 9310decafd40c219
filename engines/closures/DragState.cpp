#include "engines/closures/DragState.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "engines/closures/OutOfRange.hpp"

namespace grainbridge::closures {

namespace {

void refuse(std::string_view what, std::string_view expected, double value) {
  refuseValue("drag law", what, expected, value);
}

}  // namespace

void validate(const DragState& s) {
  // Comparisons written so that NaN fails them too.
  if (!(s.voidFraction > 0.0 && s.voidFraction <= 1.0)) refuse("void fraction", "in (0, 1]", s.voidFraction);
  if (!(s.solidFraction >= 0.0 && s.solidFraction < 1.0)) refuse("solid fraction", "in [0, 1)", s.solidFraction);
  if (!(s.diameter > 0.0)) refuse("particle diameter", "positive", s.diameter);
  if (!(s.gasDensity > 0.0)) refuse("gas density", "positive", s.gasDensity);
  if (!(s.gasViscosity > 0.0)) refuse("gas viscosity", "positive", s.gasViscosity);
  if (!(s.slip >= 0.0 && std::isfinite(s.slip))) refuse("slip velocity", "finite and >= 0", s.slip);
}

DragCoefficients dragFromBetaPerSolidFraction(const DragState& s, double betaPerSolidFraction) {
  return {s.solidFraction * betaPerSolidFraction,
          M_PI * s.diameter * s.diameter * s.diameter * betaPerSolidFraction / (6.0 * s.voidFraction)};
}

}  // namespace grainbridge::closures
