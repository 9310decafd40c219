#include "engines/closures/RadialDistribution.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::closures {

double carnahanStarlingG0(double solidFraction) {
  // Written so that NaN fails the test too.
  if (!(solidFraction >= 0.0 && solidFraction < 1.0)) {
    std::ostringstream msg;
    msg.precision(10);
    msg << "radial distribution g0: solid fraction must be in [0, 1), got " << solidFraction;
    throw Error(msg.str());
  }
  const double voidFraction = 1.0 - solidFraction;
  return (1.0 - 0.5 * solidFraction) / (voidFraction * voidFraction * voidFraction);
}

LebowitzMixture::LebowitzMixture(std::span<const double> solidFractions, const std::vector<double>& diameters)
    : diameters_(&diameters) {
  if (solidFractions.size() != diameters.size()) {
    throw Error("radial distribution g0 (Lebowitz): " + std::to_string(solidFractions.size()) + " solid fractions, " +
                std::to_string(diameters.size()) + " diameters");
  }
  double solids = 0.0;
  for (std::size_t k = 0; k < solidFractions.size(); ++k) {
    if (!(solidFractions[k] >= 0.0) || !(diameters[k] > 0.0)) {
      std::ostringstream msg;
      msg.precision(10);
      msg << "radial distribution g0 (Lebowitz): phase " << k << " has solid fraction " << solidFractions[k]
          << " and diameter " << diameters[k] << "; need >= 0 and > 0";
      throw Error(msg.str());
    }
    solids += solidFractions[k];
    sumOverDiameter_ += solidFractions[k] / diameters[k];
  }
  voidFraction_ = 1.0 - solids;
  if (!(voidFraction_ > 0.0)) {
    std::ostringstream msg;
    msg.precision(10);
    msg << "radial distribution g0 (Lebowitz): the solid fractions add up to " << solids << ", need < 1";
    throw Error(msg.str());
  }
}

void LebowitzMixture::throwPhaseOutOfRange(std::size_t l, std::size_t m) const {
  throw Error("radial distribution g0 (Lebowitz): phases " + std::to_string(l) + " and " + std::to_string(m) +
              " asked of " + std::to_string(diameters_->size()));
}

double lebowitzG0(const std::vector<double>& solidFractions, const std::vector<double>& diameters, std::size_t l,
                  std::size_t m) {
  return LebowitzMixture(solidFractions, diameters).g0(l, m);
}

double defaultG0(const std::vector<double>& solidFractions, const std::vector<double>& diameters, std::size_t l,
                 std::size_t m) {
  if (solidFractions.size() == 1 && diameters.size() == 1 && l == 0 && m == 0) {
    return carnahanStarlingG0(solidFractions[0]);
  }
  return lebowitzG0(solidFractions, diameters, l, m);
}

double maAhmadiG0(double solidFraction) {
  if (!(solidFraction >= 0.0 && solidFraction < kMaAhmadiPackingLimit)) {
    std::ostringstream msg;
    msg.precision(10);
    msg << "radial distribution g0 (Ma-Ahmadi): solid fraction must be in [0, " << kMaAhmadiPackingLimit
        << "), its packing limit, where g0 diverges; got " << solidFraction;
    throw Error(msg.str());
  }
  const double e = solidFraction;
  const double r = e / kMaAhmadiPackingLimit;
  return (1.0 + 2.5 * e + 4.5904 * e * e + 4.515439 * e * e * e) / std::pow(1.0 - r * r * r, 0.67802);
}

}  // namespace grainbridge::closures
