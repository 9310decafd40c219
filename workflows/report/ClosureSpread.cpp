#include "workflows/report/ClosureSpread.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace grainbridge::workflows::report {

namespace {

// The sample variance (n - 1); 0 for fewer than two values.
double variance(const std::vector<ClosureSampleValue>& v) {
  if (v.size() < 2) return 0.0;
  double mean = 0.0;
  for (const auto& x : v) mean += x.value;
  mean /= static_cast<double>(v.size());
  double sum = 0.0;
  for (const auto& x : v) sum += (x.value - mean) * (x.value - mean);
  return sum / static_cast<double>(v.size() - 1);
}

// The variance the closures cause: the samples' variance less their mean squared own error.
double closureVariance(const std::vector<ClosureSampleValue>& v) {
  if (v.size() < 2) return 0.0;
  double noise = 0.0;
  for (const auto& x : v) noise += x.error * x.error;
  return std::max(0.0, variance(v) - noise / static_cast<double>(v.size()));
}

}  // namespace

std::string ClosureSpread::dominant() const {
  const auto it = std::max_element(quantities.begin(), quantities.end(),
                                   [](const QuantitySpread& a, const QuantitySpread& b) { return a.share < b.share; });
  return it == quantities.end() || it->share <= 0.0 ? std::string() : it->quantity;
}

ClosureSpread closureSpread(const std::vector<ClosureSampleValue>& samples) {
  ClosureSpread out;
  std::vector<ClosureSampleValue> joint;
  std::vector<std::pair<std::string, std::vector<ClosureSampleValue>>> byQuantity;
  for (const auto& s : samples) {
    if (s.perturbed == "all") {
      joint.push_back(s);
      continue;
    }
    auto it = std::find_if(byQuantity.begin(), byQuantity.end(), [&](const auto& q) { return q.first == s.perturbed; });
    if (it == byQuantity.end()) it = byQuantity.insert(byQuantity.end(), {s.perturbed, {}});
    it->second.push_back(s);
  }
  double sumOfVariances = 0.0, sumOfScatters = 0.0;
  bool anyQuantity = false;
  for (const auto& [quantity, values] : byQuantity) {
    const double v = closureVariance(values);
    QuantitySpread q{quantity, static_cast<int>(values.size()), std::sqrt(v), 0.0};
    anyQuantity = anyQuantity || q.samples >= 2;
    sumOfVariances += v;
    sumOfScatters += variance(values);
    out.quantities.push_back(q);
  }
  for (auto& q : out.quantities) q.share = sumOfVariances > 0.0 ? q.spread * q.spread / sumOfVariances : 0.0;
  out.jointSamples = static_cast<int>(joint.size());
  if (joint.size() >= 2) {
    out.spread = std::sqrt(closureVariance(joint));
    out.scatter = std::sqrt(variance(joint));
    out.fromJoint = true;
  } else if (anyQuantity) {
    out.spread = std::sqrt(sumOfVariances);
    out.scatter = std::sqrt(sumOfScatters);
  } else {
    throw Error("closure samples: " + std::to_string(samples.size()) +
                " give no spread: it takes two joint samples (closure_samples) or two of a quantity "
                "(closure_samples_per_quantity)");
  }
  return out;
}

}  // namespace grainbridge::workflows::report
