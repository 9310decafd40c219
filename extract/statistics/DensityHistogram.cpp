#include "extract/statistics/DensityHistogram.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace grainbridge::extract::statistics {

DensityHistogram densityHistogram(std::span<const double> samples, const BinOptions& o, const std::string& what) {
  if (samples.empty()) throw Error(what + ": no samples to bin");
  double largest = samples[0];
  for (double s : samples) {
    if (!std::isfinite(s)) throw Error(what + ": a sample is not finite");
    largest = std::max(largest, s);
  }
  const bool autoHi = !(o.hi > o.lo);
  const double hi = autoHi ? largest : o.hi;
  DensityHistogram h;
  if (o.rule == BinRule::Linear) {
    if (!(o.width > 0.0)) throw Error(what + ": linear bin width must be positive, got " + std::to_string(o.width));
    if (!(hi > o.lo)) throw Error(what + ": every sample lies below the lower bin edge " + std::to_string(o.lo));
    // Whole bins: the last edge is at or just above hi so no sample is lost to rounding.
    const auto n = static_cast<std::size_t>(std::ceil((hi - o.lo) / o.width * (1.0 - 1e-12)));
    for (std::size_t k = 0; k <= std::max<std::size_t>(n, 1); ++k)
      h.edges.push_back(o.lo + static_cast<double>(k) * o.width);
  } else {
    if (!(o.lo > 0.0)) throw Error(what + ": logarithmic bins need a positive lower edge, got " + std::to_string(o.lo));
    if (o.perDecade < 1) throw Error(what + ": logarithmic bins need at least one bin per decade");
    if (!(hi > o.lo)) throw Error(what + ": every sample lies below the lower bin edge " + std::to_string(o.lo));
    const double step = 1.0 / o.perDecade;
    const auto n = static_cast<std::size_t>(std::ceil(std::log10(hi / o.lo) / step * (1.0 - 1e-12)));
    for (std::size_t k = 0; k <= std::max<std::size_t>(n, 1); ++k) {
      h.edges.push_back(o.lo * std::pow(10.0, static_cast<double>(k) * step));
    }
  }
  // With an automatic upper edge the largest sample must land in the last bin.
  if (autoHi) h.edges.back() = std::max(h.edges.back(), largest);
  const std::size_t nb = h.edges.size() - 1;
  h.counts.assign(nb, 0.0);
  for (double s : samples) {
    if (s < h.edges.front() || s > h.edges.back() || (s == h.edges.back() && !autoHi)) {
      ++h.outside;
      continue;
    }
    auto k = static_cast<std::size_t>(std::upper_bound(h.edges.begin(), h.edges.end(), s) - h.edges.begin());
    k = std::min(k == 0 ? 0 : k - 1, nb - 1);  // s == last edge goes into the last bin
    h.counts[k] += 1.0;
  }
  h.samples = samples.size();
  const auto n = static_cast<double>(h.samples);
  for (std::size_t k = 0; k < nb; ++k) {
    const double w = h.width(k);
    h.centre.push_back(0.5 * (h.edges[k] + h.edges[k + 1]));
    h.density.push_back(h.counts[k] / (n * w));
    h.error.push_back(std::sqrt(std::max(h.counts[k], 1.0)) / (n * w));
  }
  return h;
}

}  // namespace grainbridge::extract::statistics
