#include "core/averaging/RatioOfMeans.hpp"

#include <vector>

#include "core/Error.hpp"
#include "core/averaging/BlockAverage.hpp"

namespace grainbridge::core::averaging {

Ratio ratioOfMeans(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size()) {
    throw Error("ratio of means: series of " + std::to_string(a.size()) + " and " + std::to_string(b.size()) +
                " samples");
  }
  const double meanA = blockAverage(a).mean;
  const double meanB = blockAverage(b).mean;
  if (meanB == 0.0) throw Error("ratio of means: the denominator's mean is zero");
  const double r = meanA / meanB;
  std::vector<double> d(a.size());
  for (std::size_t k = 0; k < a.size(); ++k) d[k] = (a[k] - r * b[k]) / meanB;
  return {r, blockAverage(d).standardError};
}

}  // namespace grainbridge::core::averaging
