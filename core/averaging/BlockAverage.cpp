#include "core/averaging/BlockAverage.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::core::averaging {

namespace {
// Mean and naive standard error sqrt(var / (n - 1)), var the biased variance.
std::pair<double, double> meanAndError(const std::vector<double>& x) {
  const auto n = static_cast<double>(x.size());
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= n;
  double var = 0.0;
  for (double v : x) var += (v - mean) * (v - mean);
  var /= n;
  return {mean, x.size() > 1 ? std::sqrt(var / (n - 1.0)) : 0.0};
}
// B times the variance of the mean of B consecutive samples of unit variance whose correlation
// at lag k is rho^k: 1 + 2 sum_{k<B} (1 - k/B) rho^k, summed.
double blockedVarianceFactor(double b, double rho) {
  return (1.0 + rho) / (1.0 - rho) - 2.0 * rho * (1.0 - std::pow(rho, b)) / (b * std::pow(1.0 - rho, 2));
}

struct Extrapolated {
  double standardError = 0.0;
  bool capped = false;  // the level was too far below the plateau for the model to say how far
};

// The blocked error at block size b (m blocks of n samples) extrapolated to the plateau under an
// exponential correlation (header). The expected naive variance of m block means is
// (Var_b - Var_mb) / (m - 1), Var_L the variance of the mean of L samples; its ratio h to the
// variance of the whole mean V follows from rho, and rho from V itself: the integrated
// correlation time tau = n V / (2 sigma^2), rho = (2 tau - 1) / (2 tau + 1), sigma^2 the
// variance of one sample (the series' biased variance plus V). V = SE_b^2 / h is found by a
// damped fixed point. White noise has tau = 1/2, rho = 0, h = 1: its error is left as it is.
Extrapolated towardsThePlateau(double levelSe, double firstSe, double b, double m, double n) {
  constexpr double kLargestCorrection = 2.0;  // in variance: at most sqrt(2) on the error
  const double level = levelSe * levelSe;
  if (level == 0.0 || b <= 1.0) return {levelSe, false};
  const double biasedVariance = (n - 1.0) * firstSe * firstSe;
  double v = level;
  bool capped = false;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double tau = std::min(n, std::max(0.5, n * v / (2.0 * (biasedVariance + v))));
    const double rho = (2.0 * tau - 1.0) / (2.0 * tau + 1.0);
    double h = 1.0;
    if (rho > 0.0) {
      const double blocked =
          (blockedVarianceFactor(b, rho) / b - blockedVarianceFactor(m * b, rho) / (m * b)) / (m - 1.0);
      h = blocked / (blockedVarianceFactor(n, rho) / n);
    }
    capped = h < 1.0 / kLargestCorrection;
    const double next = level / std::max(h, 1.0 / kLargestCorrection);
    if (std::abs(next - v) <= 1e-12 * v) return {std::sqrt(next), capped};
    v = 0.5 * (v + next);
  }
  return {std::sqrt(v), capped};
}

}  // namespace

BlockAverage blockAverage(std::span<const double> samples) {
  if (samples.empty()) throw Error("block average: the series is empty");
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!std::isfinite(samples[i])) {
      throw Error("block average: sample " + std::to_string(i) + " is " + std::to_string(samples[i]));
    }
  }
  BlockAverage out;
  out.samples = samples.size();
  std::vector<double> level(samples.begin(), samples.end());
  const auto [mean, plainError] = meanAndError(level);
  out.mean = mean;
  if (samples.size() < BlockAverage::kMinSamplesForBlocking) {
    out.method = BlockAverage::Method::PlainFewSamples;
    out.standardError = plainError;
    out.levelStandardError = plainError;
    out.standardErrorUncertainty = samples.size() > 1 ? plainError / std::sqrt(2.0 * (samples.size() - 1.0)) : 0.0;
    out.standardErrorByLevel = {plainError};
    return out;
  }
  out.method = BlockAverage::Method::Blocking;
  const double n = static_cast<double>(samples.size());
  std::vector<std::size_t> blocks;
  while (level.size() >= 2) {
    out.standardErrorByLevel.push_back(meanAndError(level).second);
    blocks.push_back(level.size());
    std::vector<double> next(level.size() / 2);
    for (std::size_t i = 0; i < next.size(); ++i) next[i] = 0.5 * (level[2 * i] + level[2 * i + 1]);
    level.swap(next);
  }
  const double se1 = out.standardErrorByLevel.front();
  // The level used: the first that meets the criterion, else the deepest with kMinBlocks blocks.
  std::size_t used = 0;
  for (std::size_t l = 0; l < out.standardErrorByLevel.size(); ++l) {
    // A level of fewer than kMinBlocks blocks has an error of one or two degrees of freedom, which
    // can come out near zero by chance and then meets the criterion below: a 151-frame series
    // whose levels rose to 1.4e-4 reported 8.9e-7 from its two blocks (issue 63). Never use one.
    if (blocks[l] < BlockAverage::kMinBlocks) break;
    used = l;
    const double b = std::ldexp(1.0, static_cast<int>(l));
    const double ratio = se1 > 0.0 ? out.standardErrorByLevel[l] / se1 : 1.0;
    if (b * b * b > 2.0 * n * std::pow(ratio, 4)) {
      out.plateauReached = true;
      break;
    }
  }
  out.blockSize = std::size_t{1} << used;
  out.levelStandardError = out.standardErrorByLevel[used];
  const double m = static_cast<double>(blocks[used]);
  const auto extrapolated = towardsThePlateau(out.levelStandardError, se1, static_cast<double>(out.blockSize), m, n);
  out.standardError = extrapolated.standardError;
  if (extrapolated.capped) out.plateauReached = false;
  // The error of a standard error: half the relative error 2 / (m - 1) of a variance from m blocks.
  out.standardErrorUncertainty = out.standardError / std::sqrt(2.0 * (m - 1.0));
  return out;
}

std::vector<BlockAverage> blockAverageCells(const std::vector<std::vector<double>>& frames) {
  if (frames.empty()) throw Error("block average of cells: no frames");
  const std::size_t cells = frames.front().size();
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (frames[f].size() != cells) {
      throw Error("block average of cells: frame " + std::to_string(f) + " has " + std::to_string(frames[f].size()) +
                  " cells, frame 0 has " + std::to_string(cells));
    }
  }
  std::vector<BlockAverage> out;
  out.reserve(cells);
  std::vector<double> series(frames.size());
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::size_t f = 0; f < frames.size(); ++f) series[f] = frames[f][c];
    out.push_back(blockAverage(series));
  }
  return out;
}

}  // namespace grainbridge::core::averaging
