#include "extract/statistics/PairCorrelation.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "core/Error.hpp"
#include "extract/geometry/PairSearch.hpp"
#include "extract/geometry/PeriodicBox.hpp"

namespace grainbridge::extract::statistics {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Pseudo-random but reproducible group of point k: contact and particle arrays are often
// sorted spatially by the engine, and groups of neighbours would make the jackknife blind to
// the correlation it is meant to see.
std::size_t groupOf(std::size_t k, int groups) {
  std::uint64_t z = static_cast<std::uint64_t>(k) + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<std::size_t>(z % static_cast<std::uint64_t>(groups));
}

// Jackknife standard error of each bin from delete-one replicates.
std::vector<double> jackknifeError(const std::vector<std::vector<double>>& reps, std::size_t bins) {
  std::vector<double> err(bins, kNaN);
  const auto g = static_cast<double>(reps.size());
  if (reps.size() < 2) return err;
  for (std::size_t k = 0; k < bins; ++k) {
    double mean = 0.0;
    bool ok = true;
    for (const auto& r : reps) {
      ok = ok && std::isfinite(r[k]);
      mean += r[k];
    }
    if (!ok) continue;
    mean /= g;
    double ss = 0.0;
    for (const auto& r : reps) ss += (r[k] - mean) * (r[k] - mean);
    err[k] = std::sqrt((g - 1.0) / g * ss);
  }
  return err;
}
}  // namespace

void CorrelationAccumulator::RawSums::resize(std::size_t bins) {
  product.assign(bins, 0.0);
  count.assign(bins, 0.0);
  pairSum.assign(bins, Vec3::Zero());
}

CorrelationAccumulator::RawSums& CorrelationAccumulator::RawSums::operator-=(const RawSums& o) {
  for (std::size_t k = 0; k < product.size(); ++k) {
    product[k] -= o.product[k];
    count[k] -= o.count[k];
    pairSum[k] -= o.pairSum[k];
  }
  sumW -= o.sumW;
  sumW2 -= o.sumW2;
  points -= o.points;
  return *this;
}

CorrelationAccumulator::Sums& CorrelationAccumulator::Sums::operator+=(const Sums& o) {
  if (product.empty()) {
    product.assign(o.product.size(), 0.0);
    count.assign(o.count.size(), 0.0);
  }
  for (std::size_t k = 0; k < product.size(); ++k) {
    product[k] += o.product[k];
    count[k] += o.count[k];
  }
  sumW += o.sumW;
  sumW2 += o.sumW2;
  points += o.points;
  return *this;
}

CorrelationAccumulator::Sums& CorrelationAccumulator::Sums::operator-=(const Sums& o) {
  for (std::size_t k = 0; k < product.size(); ++k) {
    product[k] -= o.product[k];
    count[k] -= o.count[k];
  }
  sumW -= o.sumW;
  sumW2 -= o.sumW2;
  points -= o.points;
  return *this;
}

CorrelationAccumulator::CorrelationAccumulator(const CorrelationOptions& options, FrameNormalisation normalisation,
                                               std::string what)
    : options_(options), normalisation_(normalisation), what_(std::move(what)) {
  if (!(options.binWidth > 0.0) || !std::isfinite(options.binWidth)) {
    throw Error(what_ + ": bin width dr must be positive, got " + std::to_string(options.binWidth));
  }
  if (!(options.rMax > 0.0) || !std::isfinite(options.rMax)) {
    throw Error(what_ + ": r_max must be positive, got " + std::to_string(options.rMax));
  }
  if (options.groups < 2)
    throw Error(what_ + ": need at least 2 jackknife groups, got " + std::to_string(options.groups));
  bins_ = static_cast<std::size_t>(std::ceil(options.rMax / options.binWidth * (1.0 - 1e-12)));
}

void CorrelationAccumulator::add(const core::data::Domain& domain, std::span<const Vec3> positions,
                                 std::span<const double> weights) {
  std::vector<Vec3> w;
  w.reserve(weights.size());
  for (double x : weights) w.emplace_back(x, 0.0, 0.0);
  addVectors(domain, positions, w, true);
}

void CorrelationAccumulator::add(const core::data::Domain& domain, std::span<const Vec3> positions,
                                 std::span<const Vec3> weights) {
  if (normalisation_ == FrameNormalisation::DivideByMean) {
    throw Error(what_ + ": division by the frame mean needs scalar weights");
  }
  addVectors(domain, positions, weights, false);
}

void CorrelationAccumulator::addVectors(const core::data::Domain& domain, std::span<const Vec3> positions,
                                        std::span<const Vec3> weights, bool scalar) {
  const int kind = scalar ? 1 : 2;
  if (kind_ != 0 && kind_ != kind) throw Error(what_ + ": scalar and vector weights cannot be mixed");
  kind_ = kind;
  if (positions.size() != weights.size()) {
    throw Error(what_ + ": " + std::to_string(positions.size()) + " positions but " + std::to_string(weights.size()) +
                " weights");
  }
  // Point groups are kept for the first frame only: they are used when it stays the only one.
  const bool first = frames_.empty();
  RawSums total;
  total.resize(bins_);
  std::vector<RawSums> groups;
  if (first) {
    groups.resize(static_cast<std::size_t>(options_.groups));
    for (auto& g : groups) g.resize(bins_);
  }
  std::vector<std::size_t> group(positions.size());
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (!weights[i].allFinite()) throw Error(what_ + ": weight " + std::to_string(i) + " is not finite");
    group[i] = groupOf(i, options_.groups);
    total.sumW += weights[i];
    total.sumW2 += weights[i].squaredNorm();
    total.points += 1.0;
    if (first) {
      RawSums& g = groups[group[i]];
      g.sumW += weights[i];
      g.sumW2 += weights[i].squaredNorm();
      g.points += 1.0;
    }
  }
  const double dr = options_.binWidth;
  const std::size_t nb = bins_;
  auto accumulate = [](RawSums& s, std::size_t k, double p, const Vec3& sum) {
    s.product[k] += p;
    s.count[k] += 1.0;
    s.pairSum[k] += sum;
  };
  const double rMax = options_.rMax;
  try {
    const geometry::PeriodicBox box(domain);
    // Past half a periodic edge a pair would have two images within r_max, and Eq. 6.12 counts
    // each pair once: the correlation would be wrong there, not merely noisy.
    if (rMax > box.maxUniqueDistance()) {
      throw Error("r_max = " + std::to_string(rMax) + " exceeds half the shortest periodic box edge (" +
                  std::to_string(box.maxUniqueDistance()) + "); the minimum image would not be unique");
    }
    // The search keeps r <= cutoff and the bins end before r_max: the next double below it.
    // Bins do not need the last bits of r, so the search need not measure them again.
    const geometry::PairSearch search(box, positions, std::nextafter(rMax, 0.0),
                                      geometry::PairSearch::Lengths::RoundOff);
    // Per pair: one dot product and two or three bin updates; the pair search dominates.
    search.forEachPair([&](std::size_t i, std::size_t j, double r) {
      const auto k = static_cast<std::size_t>(r / dr);
      if (k >= nb) return;
      const double p = weights[i].dot(weights[j]);
      const Vec3 sum = weights[i] + weights[j];
      accumulate(total, k, p, sum);
      if (first) {
        accumulate(groups[group[i]], k, p, sum);
        if (group[j] != group[i]) accumulate(groups[group[j]], k, p, sum);
      }
    });
  } catch (const Error& e) {
    throw e.withContext(what_);
  }
  if (normalisation_ == FrameNormalisation::DivideByMean && !(total.sumW[0] > 0.0)) {
    throw Error(what_ + ": the weights of a frame have a non-positive mean, so they cannot be divided by it");
  }
  frames_.push_back(normalise(total));
  if (first) {
    firstFrame_ = std::move(total);
    groupsOfFirstFrame_ = std::move(groups);
  }
}

CorrelationAccumulator::Sums CorrelationAccumulator::normalise(const RawSums& raw) const {
  Sums s;
  s.count = raw.count;
  s.points = raw.points;
  s.product = raw.product;
  s.sumW = raw.sumW;
  s.sumW2 = raw.sumW2;
  if (!(raw.points > 0.0)) return s;
  const Vec3 m = raw.sumW / raw.points;
  switch (normalisation_) {
    case FrameNormalisation::None:
      break;
    case FrameNormalisation::DivideByMean: {
      // f = w / m: every product scales by 1/m^2.
      const double inv2 = 1.0 / (m[0] * m[0]);
      for (double& p : s.product) p *= inv2;
      s.sumW = Vec3(raw.points, 0.0, 0.0);
      s.sumW2 = raw.sumW2 * inv2;
      break;
    }
    case FrameNormalisation::SubtractMean: {
      // (w_i - m).(w_j - m) = w_i.w_j - m.(w_i + w_j) + |m|^2.
      for (std::size_t k = 0; k < s.product.size(); ++k) {
        s.product[k] = raw.product[k] - m.dot(raw.pairSum[k]) + raw.count[k] * m.squaredNorm();
      }
      s.sumW = Vec3::Zero();
      s.sumW2 = raw.sumW2 - raw.points * m.squaredNorm();
      break;
    }
  }
  return s;
}

std::vector<double> CorrelationAccumulator::correlation(const Sums& s) const {
  std::vector<double> v(bins_, kNaN);
  for (std::size_t k = 0; k < bins_; ++k) {
    if (s.count[k] > 0.5) v[k] = s.product[k] / s.count[k];
  }
  return v;
}

std::vector<double> CorrelationAccumulator::normalisedCorrelation(const Sums& s) const {
  std::vector<double> c(bins_, kNaN);
  if (!(s.points > 0.0)) return c;
  const Vec3 mean = s.sumW / s.points;
  const double m2 = mean.squaredNorm();
  const double var = s.sumW2 / s.points - m2;
  if (!(var > 0.0)) return c;
  for (std::size_t k = 0; k < bins_; ++k) {
    if (s.count[k] > 0.5) c[k] = (s.product[k] / s.count[k] - m2) / var;
  }
  return c;
}

CorrelationFunction CorrelationAccumulator::result() const {
  if (frames_.empty()) throw Error(what_ + ": no frames were added");
  Sums total;
  for (const auto& f : frames_) total += f;
  CorrelationFunction out;
  out.frames = frames_.size();
  out.points = static_cast<std::size_t>(total.points);
  const Vec3 mean = total.sumW / std::max(total.points, 1.0);
  out.mean = mean.norm();
  out.meanSquare = total.sumW2 / std::max(total.points, 1.0);
  if (!(out.meanSquare - mean.squaredNorm() > 1e-12 * out.meanSquare)) {
    throw Error(what_ + ": the weights have no spread (all equal), so the normalised correlation is undefined");
  }
  for (std::size_t k = 0; k < bins_; ++k) {
    const double lo = static_cast<double>(k) * options_.binWidth;
    const double hi = std::min(lo + options_.binWidth, options_.rMax);
    out.rLo.push_back(lo);
    out.rHi.push_back(hi);
    out.r.push_back(0.5 * (lo + hi));
    out.pairs.push_back(total.count[k]);
  }
  out.value = correlation(total);
  out.normalised = normalisedCorrelation(total);

  // Delete-one replicates: frames when there are several, else point groups of the one frame,
  // each re-normalised with the mean of the points it keeps.
  std::vector<Sums> reps;
  if (frames_.size() >= 2) {
    out.resampling = "frames";
    for (const auto& f : frames_) {
      Sums s = total;
      s -= f;
      reps.push_back(std::move(s));
    }
  } else {
    out.resampling = "point groups";
    for (const auto& g : groupsOfFirstFrame_) {
      RawSums s = firstFrame_;
      s -= g;
      reps.push_back(normalise(s));
    }
  }
  std::vector<std::vector<double>> repValue;
  for (const auto& s : reps) {
    repValue.push_back(correlation(s));
    out.replicateNormalised.push_back(normalisedCorrelation(s));
  }
  out.error = jackknifeError(repValue, bins_);
  out.normalisedError = jackknifeError(out.replicateNormalised, bins_);
  return out;
}

}  // namespace grainbridge::extract::statistics
