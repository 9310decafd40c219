#include "engines/closures/KineticState.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "engines/closures/OutOfRange.hpp"
#include "engines/closures/RadialDistribution.hpp"

namespace grainbridge::closures {

namespace {

void refuse(std::string_view what, std::string_view expected, double value) {
  refuseValue("kinetic theory", what, expected, value);
}

}  // namespace

double contactG0(const KineticState& s) { return s.g0 > 0.0 ? s.g0 : carnahanStarlingG0(s.solidFraction); }

void validate(const KineticState& s) {
  // Each test is written as !(valid) so that NaN is refused too; infinities are refused
  // explicitly because they would pass a one-sided bound.
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!(s.solidFraction >= 0.0 && s.solidFraction < 1.0)) refuse("solid fraction", "in [0, 1)", s.solidFraction);
  if (!(finite(s.granularTemperature) && s.granularTemperature >= 0.0)) {
    refuse("granular temperature [m^2/s^2]", "finite and >= 0", s.granularTemperature);
  }
  if (!(finite(s.diameter) && s.diameter > 0.0)) refuse("particle diameter [m]", "finite and > 0", s.diameter);
  if (!(finite(s.density) && s.density > 0.0)) refuse("particle density [kg/m^3]", "finite and > 0", s.density);
  if (!(s.restitution > 0.0 && s.restitution <= 1.0)) refuse("restitution", "in (0, 1]", s.restitution);
  if (!(finite(s.gasDragCoefficient) && s.gasDragCoefficient >= 0.0)) {
    refuse("gas drag coefficient [kg/(m^3 s)]", "finite and >= 0", s.gasDragCoefficient);
  }
  if (s.g0 != 0.0) {
    if (!(finite(s.g0) && s.g0 > 0.0)) refuse("g0", "finite and > 0", s.g0);
    if (!(finite(s.contactSum) && s.contactSum >= 0.0)) refuse("sum eps_l g0_ml", "finite and >= 0", s.contactSum);
    if (!(finite(s.dissipationSum) && s.dissipationSum >= 0.0))
      refuse("sum eps_l g0_ll", "finite and >= 0", s.dissipationSum);
  }
}

}  // namespace grainbridge::closures
