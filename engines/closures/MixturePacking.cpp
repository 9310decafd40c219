#include "engines/closures/MixturePacking.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::closures {

namespace {

// The phases' diameters (> 0) and maximum packings (in (0, 1)), one of each per phase.
void checkPhases(const std::string& where, std::span<const double> diameters, std::span<const double> packings) {
  if (packings.size() != diameters.size())
    throw Error(where + std::to_string(diameters.size()) + " diameters and " + std::to_string(packings.size()) +
                " maximum packings");
  for (std::size_t k = 0; k < diameters.size(); ++k) {
    if (!(diameters[k] > 0.0)) throw Error(where + "diameter " + std::to_string(k) + " is not positive");
    if (!(packings[k] > 0.0 && packings[k] < 1.0))
      throw Error(where + "maximum packing " + std::to_string(k) + " is not in (0, 1)");
  }
}

void checkMixture(std::string_view what, std::span<const double> fractions, std::span<const double> diameters,
                  std::span<const double> packings) {
  const std::string where = std::string(what) + " packing: ";
  if (diameters.size() != fractions.size())
    throw Error(where + std::to_string(fractions.size()) + " solids fractions and " + std::to_string(diameters.size()) +
                " diameters");
  checkPhases(where, diameters, packings);
  double total = 0.0;
  for (std::size_t k = 0; k < fractions.size(); ++k) {
    if (!(fractions[k] >= 0.0)) throw Error(where + "solids fraction " + std::to_string(k) + " is negative or NaN");
    total += fractions[k];
  }
  if (!(total > 0.0)) throw Error(where + "no solids: a composition needs a positive solids fraction");
}

// The phases from coarsest to finest (equal diameters keep their order).
std::vector<std::size_t> coarseToFine(std::span<const double> diameters) {
  std::vector<std::size_t> order(diameters.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return diameters[a] > diameters[b]; });
  return order;
}

}  // namespace

std::string_view toString(PackingLimit limit) {
  switch (limit) {
    case PackingLimit::Fixed:
      return "fixed";
    case PackingLimit::YuStandish:
      return "yu_standish";
    case PackingLimit::Gera:
      return "gera";
  }
  return "fixed";
}

PackingLimit packingLimitFromString(std::string_view name) {
  for (PackingLimit limit : {PackingLimit::Fixed, PackingLimit::YuStandish, PackingLimit::Gera}) {
    if (name == toString(limit)) return limit;
  }
  throw Error("packing limit \"" + std::string(name) + "\" is not one of fixed, yu_standish, gera");
}

namespace {

// Eqs. 22-25 with the phases' order from coarsest to finest given. A fraction a hair below zero
// (round-off in a cell a phase leaves) is no share of the mix.
double yuStandishOrdered(std::span<const double> solidFractions, std::span<const double> diameters,
                         std::span<const double> maxPackings, std::span<const std::size_t> order) {
  double total = 0.0;
  for (double eps : solidFractions) total += std::max(eps, 0.0);
  double packing = 1.0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::size_t pi = order[i];
    const double Pi = maxPackings[pi];
    double sum = 0.0;
    for (std::size_t j = 0; j < order.size(); ++j) {
      if (j == i) continue;
      const std::size_t pj = order[j];
      const double r = std::min(diameters[pi], diameters[pj]) / std::max(diameters[pi], diameters[pj]);  // (25)
      if (r > 0.741) continue;                                                                           // P_ij = P_i
      const double Pij = Pi + Pi * (1.0 - Pi) * (1.0 - 2.35 * r + 1.35 * r * r);                         // (23)
      const double shift = (1.0 - r * r) / (2.0 - Pi);
      const double Xij = j < i ? shift : 1.0 - shift;  // (24): j coarser than i, or finer
      sum += (1.0 - Pi / Pij) * (std::max(solidFractions[pj], 0.0) / total) / Xij;
    }
    packing = std::min(packing, Pi / (1.0 - sum));  // (22)
  }
  return packing;
}

}  // namespace

double yuStandishPacking(std::span<const double> solidFractions, std::span<const double> diameters,
                         std::span<const double> maxPackings) {
  checkMixture("Yu-Standish", solidFractions, diameters, maxPackings);
  return yuStandishOrdered(solidFractions, diameters, maxPackings, coarseToFine(diameters));
}

double fedorsLandelPacking(std::span<const double> solidFractions, std::span<const double> diameters,
                           std::span<const double> maxPackings) {
  checkMixture("Fedors-Landel", solidFractions, diameters, maxPackings);
  if (solidFractions.size() != 2)
    throw Error("Fedors-Landel packing is of a binary mixture, not of " + std::to_string(solidFractions.size()) +
                " phases");
  const std::vector<std::size_t> order = coarseToFine(diameters);
  const std::size_t coarse = order[0], fine = order[1];
  const double PL = maxPackings[coarse], PS = maxPackings[fine];
  const double r = diameters[fine] / diameters[coarse];
  const double xL = solidFractions[coarse] / (solidFractions[coarse] + solidFractions[fine]);
  const double mixed = PL + (1.0 - PL) * PS;
  if (xL <= PL / mixed) return ((PL - PS) + (1.0 - std::sqrt(r)) * (1.0 - PL) * PS) * mixed * xL / PL + PS;
  return (1.0 - std::sqrt(r)) * mixed * (1.0 - xL) + PL;
}

MixturePacking::MixturePacking(PackingLimit limit, double fixedVoidFraction, std::vector<double> diameters,
                               std::vector<double> maxPackings)
    : limit_(limit),
      fixedVoidFraction_(fixedVoidFraction),
      diameters_(std::move(diameters)),
      maxPackings_(std::move(maxPackings)) {
  if (limit_ == PackingLimit::Fixed) return;
  checkPhases("packing limit " + std::string(toString(limit_)) + ": ", diameters_, maxPackings_);
  if (limit_ == PackingLimit::Gera && diameters_.size() > 2)
    throw Error("packing limit gera is of a binary mixture, not of " + std::to_string(diameters_.size()) + " phases");
  order_ = coarseToFine(diameters_);
  if (!diameters_.empty()) coarsestPacking_ = maxPackings_[order_.front()];
}

double MixturePacking::criticalVoidFraction(std::span<const double> solidFractions) const {
  if (!byComposition()) return fixedVoidFraction_;
  double total = 0.0;
  for (double eps : solidFractions) total += std::max(eps, 0.0);
  if (!(total > 0.0)) return 1.0 - coarsestPacking_;
  if (limit_ == PackingLimit::YuStandish)
    return 1.0 - yuStandishOrdered(solidFractions, diameters_, maxPackings_, order_);
  const std::array<double, 2> eps{std::max(solidFractions[0], 0.0), std::max(solidFractions[1], 0.0)};
  return std::max(kGeraLeastVoidFraction, 1.0 - fedorsLandelPacking(eps, diameters_, maxPackings_));
}

}  // namespace grainbridge::closures
