#pragma once
// A probability density estimated by binning samples: density_k = n_k / (N w_k), where N counts
// every sample (also those outside the binned range), so the histogram estimates the density
// of the whole sample, as the force PDFs of Figs. 6.12(a), 6.14 and 6.15 do. Errors are
// Poisson: sqrt(n_k) / (N w_k), with n_k = 0 given the error of one count.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace grainbridge::extract::statistics {

enum class BinRule {
  Linear,       // equal widths `width` from `lo` up to `hi`
  Logarithmic,  // `perDecade` equal steps in log10 from `lo` (> 0) up to `hi`
};

struct BinOptions {
  BinRule rule = BinRule::Linear;
  double lo = 0.0;
  // Upper edge; <= lo means "the largest sample" (the last bin is then closed on the right).
  double hi = 0.0;
  double width = 0.1;  // linear bins, in units of the sample (f = F_n / <F_n>: mean forces)
  int perDecade = 10;  // logarithmic bins
};

struct DensityHistogram {
  std::vector<double> edges;    // size bins + 1
  std::vector<double> centre;   // arithmetic bin centre (the fit integrates over the bin instead)
  std::vector<double> counts;   // n_k
  std::vector<double> density;  // n_k / (N w_k)
  std::vector<double> error;    // Poisson error of density
  std::size_t samples = 0;      // N, all samples, including those outside [edges.front(), edges.back()]
  std::size_t outside = 0;      // samples not in any bin

  [[nodiscard]] std::size_t bins() const { return counts.size(); }
  [[nodiscard]] double width(std::size_t k) const { return edges[k + 1] - edges[k]; }
};

// Throws grainbridge::Error naming `what` when there are no samples, a sample is not finite, or
// the options give no bins.
DensityHistogram densityHistogram(std::span<const double> samples, const BinOptions& options,
                                  const std::string& what = "histogram");

}  // namespace grainbridge::extract::statistics
