#include "engines/closures/InertialRheology.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"

namespace grainbridge::closures {

namespace {

void requireGrains(const InertialRheology::Grains& g) {
  if (!(g.diameter > 0.0) || !(g.density > 0.0)) {
    std::ostringstream msg;
    msg << "mu(I) rheology: the grains need a positive diameter and density, got " << g.diameter << " m and "
        << g.density << " kg/m3";
    throw Error(msg.str());
  }
}

}  // namespace

InertialRheology InertialRheology::fitted(Grains grains, Law law) {
  requireGrains(grains);
  if (!(law.staticRatio >= 0.0) || !(law.limitRatio >= law.staticRatio) || !std::isfinite(law.limitRatio) ||
      !(law.inertialNumberScale > 0.0) || !std::isfinite(law.inertialNumberScale)) {
    std::ostringstream msg;
    msg << "mu(I) rheology: the fit needs 0 <= mu_s <= mu_2 and I_0 > 0, got mu_s " << law.staticRatio << ", mu_2 "
        << law.limitRatio << ", I_0 " << law.inertialNumberScale;
    throw Error(msg.str());
  }
  InertialRheology r;
  r.grains_ = grains;
  r.law_ = law;
  return r;
}

InertialRheology InertialRheology::tabulated(Grains grains, std::vector<double> inertialNumbers,
                                             std::vector<double> stressRatios) {
  requireGrains(grains);
  if (inertialNumbers.empty() || inertialNumbers.size() != stressRatios.size()) {
    throw Error("mu(I) rheology: the table needs as many stress ratios as inertial numbers, at least one; got " +
                std::to_string(inertialNumbers.size()) + " and " + std::to_string(stressRatios.size()));
  }
  for (std::size_t k = 0; k < inertialNumbers.size(); ++k) {
    const double low = k == 0 ? 0.0 : inertialNumbers[k - 1];
    if (!(inertialNumbers[k] > low) || !std::isfinite(inertialNumbers[k]) || !(stressRatios[k] >= 0.0) ||
        !std::isfinite(stressRatios[k])) {
      std::ostringstream msg;
      msg << "mu(I) rheology: point " << k << " (I " << inertialNumbers[k] << ", mu " << stressRatios[k]
          << ") is not a finite mu >= 0 at an I above the previous point's and above 0";
      throw Error(msg.str());
    }
  }
  InertialRheology r;
  r.grains_ = grains;
  r.points_ = std::move(inertialNumbers);
  r.ratios_ = std::move(stressRatios);
  return r;
}

double InertialRheology::stressRatio(double inertialNumber) const {
  if (points_.empty()) {
    // (mu_2 - mu_s) I / (I + I_0): the same law without the division by I at I = 0.
    return law_.staticRatio +
           (law_.limitRatio - law_.staticRatio) * inertialNumber / (inertialNumber + law_.inertialNumberScale);
  }
  if (inertialNumber <= points_.front()) return ratios_.front();
  if (inertialNumber >= points_.back()) return ratios_.back();
  const auto hi = static_cast<std::size_t>(std::upper_bound(points_.begin(), points_.end(), inertialNumber) -
                                           points_.begin());
  const std::size_t lo = hi - 1;
  const double w = (inertialNumber - points_[lo]) / (points_[hi] - points_[lo]);
  return (1.0 - w) * ratios_[lo] + w * ratios_[hi];
}

double InertialRheology::inertialNumber(double shearRate, double pressure) const {
  return shearRate * grains_.diameter / std::sqrt(pressure / grains_.density);
}

std::string InertialRheology::describe() const {
  std::ostringstream out;
  out.precision(4);
  if (points_.empty()) {
    out << "mu_s " << law_.staticRatio << ", mu_2 " << law_.limitRatio << ", I_0 " << law_.inertialNumberScale;
  } else {
    out << points_.size() << " points, I " << points_.front() << "-" << points_.back();
  }
  return out.str();
}

}  // namespace grainbridge::closures
