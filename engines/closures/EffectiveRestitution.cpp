#include "engines/closures/EffectiveRestitution.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "engines/closures/OutOfRange.hpp"

namespace grainbridge::closures {

namespace {

void refuse(std::string_view what, std::string_view expected, double value) {
  refuseValue("effective restitution (Eq. 5.19)", what, expected, value);
}

}  // namespace

EffectiveRestitution::Result EffectiveRestitution::evaluate(double e) const {
  const double mu = params.friction;
  const double beta0 = params.tangentialRestitution;
  if (!(e > 0.0 && e <= 1.0)) refuse("the normal restitution e", "in (0, 1]", e);
  if (!(mu >= 0.0 && std::isfinite(mu))) refuse("the friction coefficient mu", "finite and >= 0", mu);
  if (!(beta0 >= -1.0 && beta0 <= 1.0)) refuse("the tangential restitution beta0", "in [-1, 1]", beta0);
  Result r;
  r.effectiveRestitution = e;
  if (mu > 0.0) {
    const double mu0 = 3.5 * mu * (1.0 + e) / (1.0 + beta0);  // Eq. 5.17
    const double ratio = mu / mu0;                            // = 2 (1 + beta0) / (7 (1 + e))
    const double arc = 1.0 - 2.0 / M_PI * std::atan(mu0);
    const double m2 = mu0 * mu0;
    r.mu0 = mu0;
    r.a1 = ratio * (M_PI * mu0 * arc + 2.0 * m2 / (1.0 + m2) * (1.0 - 2.0 * ratio));      // Eq. 5.12
    r.a2 = 5.0 * ratio * (0.5 * M_PI * mu0 * arc - m2 * m2 / ((1.0 + m2) * (1.0 + m2)));  // Eq. 5.13
    r.b1 = ratio * ratio * m2 / (1.0 + m2);                                               // Eq. 5.15
    r.b2 = 0.5 * ratio * (0.5 * M_PI * mu0 * arc + m2 / (1.0 + m2));                      // Eq. 5.16
    r.rotationalToTranslational = r.b1 / r.b2;                                            // Eq. 5.18
    r.effectiveRestitution = e - 0.5 * r.a1 + r.a2 * r.b1 / (2.0 * r.b2);                 // Eq. 5.19
  }
  r.dissipationFactor = (1.0 + e) * (1.0 - r.effectiveRestitution);  // Eqs. 5.20-5.21 as printed
  return r;
}

}  // namespace grainbridge::closures
