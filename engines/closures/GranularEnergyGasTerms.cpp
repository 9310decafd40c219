#include "engines/closures/GranularEnergyGasTerms.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "engines/closures/OutOfRange.hpp"

namespace grainbridge::closures {

namespace {

void refuse(std::string_view what, std::string_view expected, double value) {
  refuseValue("granular energy gas terms", what, expected, value);
}

}  // namespace

double GranularEnergyGasTerms::Result::slipProduction(double theta) const {
  if (!(theta > 0.0)) refuse("theta for gamma_slip (it diverges as theta -> 0)", "positive", theta);
  return slipProductionCoefficient / std::sqrt(theta);
}

GranularEnergyGasTerms::Result GranularEnergyGasTerms::evaluate(const State& s) const {
  if (!(s.solidFraction >= 0.0 && s.solidFraction < 1.0)) refuse("eps_s", "in [0, 1)", s.solidFraction);
  if (!(s.diameter > 0.0)) refuse("d", "positive", s.diameter);
  if (!(s.density > 0.0)) refuse("rho_s", "positive", s.density);
  if (!(s.radialDistribution > 0.0 && std::isfinite(s.radialDistribution)))
    refuse("g0", "finite and positive", s.radialDistribution);
  if (!(s.gasViscosity > 0.0)) refuse("mu_g", "positive", s.gasViscosity);
  if (!(s.slip >= 0.0 && std::isfinite(s.slip))) refuse("|v_g - v_s|", "finite and >= 0", s.slip);
  if (!(s.beta >= 0.0 && std::isfinite(s.beta))) refuse("beta", "finite and >= 0", s.beta);
  const double viscousSlip = s.gasViscosity * s.slip;
  Result r;
  r.slipProductionCoefficient = 81.0 * s.solidFraction * viscousSlip * viscousSlip /
                                (s.radialDistribution * std::pow(s.diameter, 3) * s.density * std::sqrt(M_PI));
  r.viscousDissipationCoefficient = 3.0 * s.beta;
  return r;
}

}  // namespace grainbridge::closures
