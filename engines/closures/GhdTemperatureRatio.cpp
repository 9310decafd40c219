#include "engines/closures/GhdTemperatureRatio.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/Error.hpp"
#include "engines/closures/RadialDistribution.hpp"

namespace grainbridge::closures {

double ghdTemperatureRatio(const std::vector<CoolingSpecies>& species, double restitution) {
  if (species.size() != 2) {
    throw Error("GHD temperature ratio: needs two species, got " + std::to_string(species.size()));
  }
  if (!(restitution > 0.0 && restitution <= 1.0)) {
    throw Error("GHD temperature ratio: restitution " + std::to_string(restitution) + " is not in (0, 1]");
  }
  std::vector<double> fractions, diameters, mass, number;
  for (const CoolingSpecies& s : species) {
    if (!(s.solidFraction > 0.0 && s.diameter > 0.0 && s.density > 0.0)) {
      throw Error("GHD temperature ratio: each species needs a positive solid fraction, diameter and density");
    }
    const double volume = std::numbers::pi / 6.0 * s.diameter * s.diameter * s.diameter;
    fractions.push_back(s.solidFraction);
    diameters.push_back(s.diameter);
    mass.push_back(s.density * volume);
    number.push_back(s.solidFraction / volume);
  }
  const LebowitzMixture chi(fractions, diameters);  // throws unless sum eps < 1
  const double a = 1.0 + restitution;
  // zeta_i at T = (r, 1); the common factor 8 sqrt(pi) / 3 left out.
  const auto zeta = [&](std::size_t i, double r) {
    const double T[2] = {r, 1.0};
    double sum = 0.0;
    for (std::size_t j = 0; j < 2; ++j) {
      const double muJI = mass[j] / (mass[i] + mass[j]);
      const double sigma = 0.5 * (diameters[i] + diameters[j]);
      sum += number[j] * chi.g0(i, j) * muJI * sigma * sigma * a *
             std::sqrt(2.0 * T[i] / mass[i] + 2.0 * T[j] / mass[j]) *
             (1.0 - 0.5 * muJI * a * (1.0 + mass[i] * T[j] / (mass[j] * T[i])));
    }
    return sum;
  };
  // zeta_1 - zeta_2 changes sign once, at the homogeneous cooling state's ratio: bisect in log r.
  const auto f = [&](double r) { return zeta(0, r) - zeta(1, r); };
  double lo = 1e-4, hi = 1e4;
  if (!(f(lo) * f(hi) < 0.0)) {
    if (f(1.0) == 0.0) return 1.0;
    throw Error("GHD temperature ratio: no root of zeta_1 = zeta_2 between 1e-4 and 1e4");
  }
  for (int k = 0; k < 200 && hi / lo > 1.0 + 1e-14; ++k) {
    const double mid = std::sqrt(lo * hi);
    (f(lo) * f(mid) <= 0.0 ? hi : lo) = mid;
  }
  return std::sqrt(lo * hi);
}

}  // namespace grainbridge::closures
