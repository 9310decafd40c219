#include "extract/statistics/CorrelationLength.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "core/Error.hpp"
#include "extract/statistics/LeastSquares.hpp"

namespace grainbridge::extract::statistics {

namespace {
struct Crossing {
  std::size_t peakBin = 0;
  double rPeak = 0.0, rCross = 0.0, peak = 0.0;
};

enum class CrossingFailure { NoBins, PeakNotPositive, NoCrossing };

// The 1/e decay of one curve; the failure reason instead when there is none.
std::optional<Crossing> findCrossing(const std::vector<double>& r, const std::vector<double>& value,
                                     const std::vector<double>& pairs, double minPairs, CrossingFailure& why) {
  auto usable = [&](std::size_t k) { return pairs[k] >= minPairs && std::isfinite(value[k]); };
  std::optional<std::size_t> best;
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (usable(k) && (!best || value[k] > value[*best])) best = k;
  }
  if (!best) {
    why = CrossingFailure::NoBins;
    return std::nullopt;
  }
  Crossing c;
  c.peakBin = *best;
  c.rPeak = r[*best];
  c.peak = value[*best];
  if (!(c.peak > 0.0)) {
    why = CrossingFailure::PeakNotPositive;
    return std::nullopt;
  }
  const double threshold = c.peak / std::exp(1.0);
  std::size_t prev = *best;
  for (std::size_t k = *best + 1; k < r.size(); ++k) {
    if (!usable(k)) continue;
    if (value[k] <= threshold) {
      const double t = (value[prev] - threshold) / (value[prev] - value[k]);
      c.rCross = r[prev] + t * (r[k] - r[prev]);
      return c;
    }
    prev = k;
  }
  why = CrossingFailure::NoCrossing;
  return std::nullopt;
}
// Delete-one jackknife standard error from the replicate estimates.
double jackknifeSpread(const std::vector<double>& x) {
  const auto g = static_cast<double>(x.size());
  double mean = 0.0;
  for (double v : x) mean += v / g;
  double ss = 0.0;
  for (double v : x) ss += (v - mean) * (v - mean);
  return std::sqrt((g - 1.0) / g * ss);
}
}  // namespace

CorrelationLength decayLength(const CorrelationFunction& c, const CorrelationLengthOptions& options) {
  CrossingFailure why{};
  const auto main = findCrossing(c.r, c.normalised, c.pairs, options.minPairs, why);
  if (!main) {
    switch (why) {
      case CrossingFailure::NoBins:
        throw Error("correlation length: no bin has " + std::to_string(options.minPairs) +
                    " or more pairs; use more points, wider bins or a larger r_max");
      case CrossingFailure::PeakNotPositive:
        throw Error(
            "correlation length: the normalised correlation is nowhere positive (peak " +
            std::to_string(c.normalised.empty() ? 0.0 : *std::max_element(c.normalised.begin(), c.normalised.end())) +
            "), so it has no decay length");
      case CrossingFailure::NoCrossing:
        throw Error("correlation length: the normalised correlation does not fall to 1/e of its peak within r_max = " +
                    std::to_string(c.rHi.empty() ? 0.0 : c.rHi.back()) + "; increase r_max");
    }
  }
  CorrelationLength out;
  out.rPeak = main->rPeak;
  out.rCross = main->rCross;
  out.peak = main->peak;
  out.length = main->rCross - main->rPeak;
  std::vector<double> lengths;
  for (const auto& rep : c.replicateNormalised) {
    CrossingFailure ignored{};
    if (const auto x = findCrossing(c.r, rep, c.pairs, options.minPairs, ignored)) {
      lengths.push_back(x->rCross - x->rPeak);
    } else {
      ++out.failedReplicates;
    }
  }
  out.replicates = lengths.size();
  out.error = std::numeric_limits<double>::quiet_NaN();
  if (out.failedReplicates == 0 && lengths.size() >= 2) out.error = jackknifeSpread(lengths);
  return out;
}

namespace {
struct ExpFit {
  double amplitude, length, lengthErrorCovariance, chi2PerDof;
  std::size_t bins;
  double rPeak, rEnd;
};

// LM fit of A e^{-(r - r_p)/xi} to one curve, weighted by sigma (the jackknife errors of the
// full curve, also for replicates so that they are fitted by the same estimator).
ExpFit fitExponential(const CorrelationFunction& c, const std::vector<double>& curve, const CorrelationLengthOptions& o,
                      const std::string& what) {
  std::optional<std::size_t> best;
  for (std::size_t k = 0; k < c.bins(); ++k) {
    if (c.pairs[k] >= o.minPairs && std::isfinite(curve[k]) && (!best || curve[k] > curve[*best])) best = k;
  }
  if (!best) throw Error(what + ": no bin has enough pairs");
  std::vector<double> r, y, s;
  for (std::size_t k = *best; k < c.bins(); ++k) {
    if (c.r[k] > o.rFitMax) break;
    if (c.pairs[k] < o.minPairs || !std::isfinite(curve[k]) || !(c.normalisedError[k] > 0.0)) continue;
    r.push_back(c.r[k]);
    y.push_back(curve[k]);
    s.push_back(c.normalisedError[k]);
  }
  if (r.size() < 3) throw Error(what + ": fewer than 3 usable bins between the peak and r_fit_max");
  const double r0 = r.front();
  // Start: amplitude at the peak, length from where C first halves (or a third of the range).
  Eigen::VectorXd p(2);
  p << y.front(), (r.back() - r0) / 3.0;
  for (std::size_t k = 1; k < r.size(); ++k) {
    if (y[k] < 0.5 * y.front()) {
      p[1] = std::max((r[k] - r0) / std::log(2.0), 1e-12);
      break;
    }
  }
  const std::size_t m = r.size();
  auto residuals = [&](const Eigen::VectorXd& x, Eigen::VectorXd& res, Eigen::MatrixXd* J) {
    for (std::size_t k = 0; k < m; ++k) {
      const auto i = static_cast<Eigen::Index>(k);
      const double e = std::exp(-(r[k] - r0) / x[1]);
      res[i] = (y[k] - x[0] * e) / s[k];
      if (J) {
        (*J)(i, 0) = -e / s[k];
        (*J)(i, 1) = -x[0] * e * (r[k] - r0) / (x[1] * x[1]) / s[k];
      }
    }
  };
  const LeastSquaresResult fit = levenbergMarquardt(residuals, m, p, what);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(fit.fisher);
  if (!lu.isInvertible()) throw Error(what + ": amplitude and length are not both constrained by the data");
  ExpFit out{};
  out.bins = m;
  out.rPeak = r0;
  out.rEnd = r.back();
  out.chi2PerDof = fit.chi2 / static_cast<double>(m - 2);
  out.amplitude = fit.params[0];
  out.length = fit.params[1];
  out.lengthErrorCovariance = std::sqrt(std::max(0.0, (lu.inverse() * out.chi2PerDof)(1, 1)));
  if (!(out.length > 0.0)) throw Error(what + ": the fitted length is not positive; the correlation does not decay");
  return out;
}

}  // namespace

ExponentialLength exponentialLength(const CorrelationFunction& c, const CorrelationLengthOptions& options) {
  const std::string what = "correlation length (exponential fit)";
  const ExpFit main = fitExponential(c, c.normalised, options, what);
  ExponentialLength out;
  out.length = main.length;
  out.amplitude = main.amplitude;
  out.lengthErrorCovariance = main.lengthErrorCovariance;
  out.rPeak = main.rPeak;
  out.rEnd = main.rEnd;
  out.chi2PerDof = main.chi2PerDof;
  out.binsUsed = main.bins;
  std::vector<double> lengths, amplitudes;
  bool failed = false;
  for (const auto& rep : c.replicateNormalised) {
    try {
      const ExpFit f = fitExponential(c, rep, options, what);
      lengths.push_back(f.length);
      amplitudes.push_back(f.amplitude);
    } catch (const Error&) {
      failed = true;  // a replicate without a decaying fit: no jackknife error
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.lengthError = !failed && lengths.size() >= 2 ? jackknifeSpread(lengths) : nan;
  out.amplitudeError = !failed && amplitudes.size() >= 2 ? jackknifeSpread(amplitudes) : nan;
  return out;
}

}  // namespace grainbridge::extract::statistics
