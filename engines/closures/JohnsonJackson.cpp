#include "engines/closures/JohnsonJackson.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "engines/closures/OutOfRange.hpp"

namespace grainbridge::closures {

namespace {

void refuse(std::string_view what, std::string_view expected, double value) {
  refuseValue("Johnson-Jackson wall (Eqs. 5.8-5.9)", what, expected, value);
}

}  // namespace

JohnsonJackson::Result JohnsonJackson::evaluate(const State& s) const {
  const Params& p = params;
  if (!(p.specularity >= 0.0 && p.specularity <= 1.0)) refuse("the specularity phi'", "in [0, 1]", p.specularity);
  if (!(p.maxSolidFraction > 0.0 && p.maxSolidFraction < 1.0))
    refuse("eps_s,max", "in (0, 1) (the solids fraction at packing)", p.maxSolidFraction);
  if (!(p.wallRestitution > 0.0 && p.wallRestitution <= 1.0)) refuse("e_w", "in (0, 1]", p.wallRestitution);
  if (p.wallEffectiveRestitution && !(*p.wallEffectiveRestitution > -1.0 && *p.wallEffectiveRestitution <= 1.0))
    refuse("e_w,eff", "in (-1, 1]", *p.wallEffectiveRestitution);
  if (!(s.solidFraction >= 0.0 && s.solidFraction < 1.0)) refuse("eps_s", "in [0, 1)", s.solidFraction);
  if (!(s.density > 0.0)) refuse("rho_s", "positive", s.density);
  if (!(s.radialDistribution > 0.0 && std::isfinite(s.radialDistribution)))
    refuse("g0", "finite and positive", s.radialDistribution);
  if (!(s.granularTemperature >= 0.0 && std::isfinite(s.granularTemperature)))
    refuse("theta", "finite and >= 0", s.granularTemperature);
  if (!(s.slipSpeed >= 0.0 && std::isfinite(s.slipSpeed))) refuse("|v_slip|", "finite and >= 0", s.slipSpeed);

  const double collisions = s.density * s.solidFraction * s.radialDistribution / p.maxSolidFraction;
  const double sqrtTheta = std::sqrt(s.granularTemperature);
  Result r;
  r.slipCoefficient = std::sqrt(3.0) * M_PI / 6.0 * p.specularity * collisions * sqrtTheta;  // Eq. 5.8
  r.shearStress = r.slipCoefficient * s.slipSpeed;
  r.slipProduction = r.shearStress * s.slipSpeed;
  // Eq. 5.9, or Eq. 5.21 with the rotation model.
  const double e = p.wallRestitution;
  const double lossFactor = p.wallEffectiveRestitution ? (1.0 + e) * (1.0 - *p.wallEffectiveRestitution) : 1.0 - e * e;
  r.wallDissipation = std::sqrt(3.0) * M_PI / 4.0 * lossFactor * collisions * s.granularTemperature * sqrtTheta;
  return r;
}

}  // namespace grainbridge::closures
