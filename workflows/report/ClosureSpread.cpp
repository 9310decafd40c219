#include "workflows/report/ClosureSpread.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace grainbridge::workflows::report {

namespace {

// The sample standard deviation (n - 1); 0 for fewer than two values.
double standardDeviation(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  double mean = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  double sum = 0.0;
  for (double x : v) sum += (x - mean) * (x - mean);
  return std::sqrt(sum / static_cast<double>(v.size() - 1));
}

}  // namespace

std::string ClosureSpread::dominant() const {
  const auto it = std::max_element(quantities.begin(), quantities.end(),
                                   [](const QuantitySpread& a, const QuantitySpread& b) { return a.share < b.share; });
  return it == quantities.end() || it->share <= 0.0 ? std::string() : it->quantity;
}

ClosureSpread closureSpread(const std::vector<ClosureSampleValue>& samples) {
  ClosureSpread out;
  std::vector<double> joint;
  std::vector<std::pair<std::string, std::vector<double>>> byQuantity;
  for (const auto& s : samples) {
    if (s.perturbed == "all") {
      joint.push_back(s.value);
      continue;
    }
    auto it = std::find_if(byQuantity.begin(), byQuantity.end(), [&](const auto& q) { return q.first == s.perturbed; });
    if (it == byQuantity.end()) it = byQuantity.insert(byQuantity.end(), {s.perturbed, {}});
    it->second.push_back(s.value);
  }
  double sumOfVariances = 0.0;
  bool anyQuantity = false;
  for (const auto& [quantity, values] : byQuantity) {
    QuantitySpread q{quantity, static_cast<int>(values.size()), standardDeviation(values), 0.0};
    anyQuantity = anyQuantity || q.samples >= 2;
    sumOfVariances += q.spread * q.spread;
    out.quantities.push_back(q);
  }
  for (auto& q : out.quantities) q.share = sumOfVariances > 0.0 ? q.spread * q.spread / sumOfVariances : 0.0;
  out.jointSamples = static_cast<int>(joint.size());
  if (joint.size() >= 2) {
    out.spread = standardDeviation(joint);
    out.fromJoint = true;
  } else if (anyQuantity) {
    out.spread = std::sqrt(sumOfVariances);
  } else {
    throw Error("closure samples: " + std::to_string(samples.size()) +
                " give no spread: it takes two joint samples (closure_samples) or two of a quantity "
                "(closure_samples_per_quantity)");
  }
  return out;
}

}  // namespace grainbridge::workflows::report
