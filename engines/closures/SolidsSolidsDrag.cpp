#include "engines/closures/SolidsSolidsDrag.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "engines/closures/OutOfRange.hpp"

namespace grainbridge::closures {

namespace {

void refuse(std::string_view what, std::string_view expected, double value) {
  refuseValue("solids-solids drag (Eq. 3.18)", what, expected, value);
}

void check(const SolidsSolidsDrag::Phase& p, const char* which) {
  if (!(p.solidFraction >= 0.0 && p.solidFraction < 1.0))
    refuse(std::string("the solid fraction of phase ") + which, "in [0, 1)", p.solidFraction);
  if (!(p.density > 0.0)) refuse(std::string("the density of phase ") + which, "positive", p.density);
  if (!(p.diameter > 0.0)) refuse(std::string("the diameter of phase ") + which, "positive", p.diameter);
}

}  // namespace

double SolidsSolidsDrag::evaluate(const Phase& l, const Phase& m, double g0, double relativeSpeed) const {
  check(l, "l");
  check(m, "m");
  if (!(params.frictionCoefficient >= 0.0)) refuse("C_f", ">= 0", params.frictionCoefficient);
  if (!(params.restitution > 0.0 && params.restitution <= 1.0)) refuse("e_lm", "in (0, 1]", params.restitution);
  if (!(g0 > 0.0 && std::isfinite(g0))) refuse("g0_lm", "finite and positive", g0);
  if (!(relativeSpeed >= 0.0 && std::isfinite(relativeSpeed)))
    refuse("|v_sl - v_sm|", "finite and >= 0", relativeSpeed);
  const double dSum = l.diameter + m.diameter;
  const double massScale = l.density * std::pow(l.diameter, 3) + m.density * std::pow(m.diameter, 3);
  return 3.0 * (1.0 + params.restitution) * (0.5 * M_PI + params.frictionCoefficient * M_PI * M_PI / 8.0) *
         l.solidFraction * l.density * m.solidFraction * m.density * dSum * dSum * g0 * relativeSpeed /
         (2.0 * M_PI * massScale);
}

}  // namespace grainbridge::closures
