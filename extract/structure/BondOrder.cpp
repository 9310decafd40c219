#include "extract/structure/BondOrder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <vector>

#include "core/Error.hpp"
#include "extract/geometry/PairSearch.hpp"
#include "extract/geometry/PeriodicBox.hpp"

namespace grainbridge::extract::structure {

namespace {

// q6m for m = 0..6; m < 0 follows from Y_6^{-m} = (-1)^m conj(Y_6^m), so a sum over m = -6..6 of
// a_m conj(b_m) is a_0 conj(b_0) + 2 Re sum_{m>0} a_m conj(b_m).
using Harmonics = std::array<std::complex<double>, 7>;

double dot(const Harmonics& a, const Harmonics& b) {
  double s = (a[0] * std::conj(b[0])).real();
  for (std::size_t m = 1; m < a.size(); ++m) s += 2.0 * (a[m] * std::conj(b[m])).real();
  return s;
}

constexpr double kSolidBond = 0.5;    // normalised s_ij at or above it: a solid bond
constexpr int kSolidBondsNeeded = 6;  // solid bonds that make a particle crystalline

}  // namespace

BondOrder bondOrder(const core::data::Domain& domain, std::span<const Vec3> positions, double cutoff) {
  if (!(cutoff > 0.0) || !std::isfinite(cutoff)) {
    throw Error("bond order: the neighbour cutoff is " + std::to_string(cutoff) + "; it must be positive");
  }
  const std::size_t n = positions.size();
  BondOrder out;
  if (n == 0) return out;
  const geometry::PeriodicBox box(domain);
  const geometry::PairSearch search(box, positions, cutoff, geometry::PairSearch::Lengths::RoundOff);
  std::vector<Harmonics> q(n, Harmonics{});
  std::vector<int> neighbours(n, 0);
  std::vector<std::pair<std::size_t, std::size_t>> bonds;
  bonds.reserve(search.expectedPairCount());
  search.forEachPair([&](std::size_t i, std::size_t j, double r) {
    if (r == 0.0) return;
    const Vec3 d = box.minimumImage(positions[i] - positions[j]);
    // Y_6m(-r) = Y_6m(r) (l even): both ends take the same harmonics.
    const double theta = std::acos(std::clamp(d[2] / r, -1.0, 1.0));
    const double phi = std::atan2(d[1], d[0]);
    for (unsigned m = 0; m <= 6; ++m) {
      const std::complex<double> y = std::sph_legendre(6, m, theta) * std::polar(1.0, m * phi);
      q[i][m] += y;
      q[j][m] += y;
    }
    ++neighbours[i];
    ++neighbours[j];
    bonds.emplace_back(i, j);
  });
  std::vector<double> norm(n, 0.0);
  double sumQ6 = 0.0;
  std::size_t withNeighbours = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (neighbours[i] == 0) continue;
    for (auto& c : q[i]) c /= static_cast<double>(neighbours[i]);
    norm[i] = std::sqrt(dot(q[i], q[i]));
    sumQ6 += std::sqrt(4.0 * M_PI / 13.0) * norm[i];
    ++withNeighbours;
  }
  std::vector<int> solidBonds(n, 0);
  for (const auto& [i, j] : bonds) {
    if (norm[i] == 0.0 || norm[j] == 0.0) continue;
    if (dot(q[i], q[j]) / (norm[i] * norm[j]) >= kSolidBond) {
      ++solidBonds[i];
      ++solidBonds[j];
    }
  }
  const auto crystalline =
      std::count_if(solidBonds.begin(), solidBonds.end(), [](int b) { return b >= kSolidBondsNeeded; });
  out.meanQ6 = withNeighbours > 0 ? sumQ6 / static_cast<double>(withNeighbours) : 0.0;
  out.crystallineShare = static_cast<double>(crystalline) / static_cast<double>(n);
  return out;
}

}  // namespace grainbridge::extract::structure
