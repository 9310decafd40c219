#pragma once
// Binned two-point correlation of a weight carried by points, the form of Eq. 6.12:
//   F(r) = sum_{i<j} delta(r_ij - r) w_i . w_j / sum_{i<j} delta(r_ij - r),
// where delta is the indicator of the bin [r_k, r_k + dr) and r_ij the minimum-image distance.
// Scalar weights (contact forces) use the product, vector weights (velocities) the dot product.
//
// Each frame's weights are first normalised as the quantity requires (FrameNormalisation):
// forces are divided by the frame's mean, f = F_n / <F_n>, velocities have the frame's mean
// removed, C = u - <u>. The accumulator does this itself, from the raw weights, so that every
// jackknife replicate is the same estimator applied to the reduced data: dropping points moves
// the mean, and a replicate that kept the full-sample mean would see the O(1/sqrt(N)) shift of
// the mean in every bin, which the normalised estimator does not have (a ~4x overestimate of
// the error of a flat F(r) in tests). Frames are pooled by adding their normalised numerators
// and pair counts.
//
// Normalised form: C(r) = (F(r) - |<w>|^2) / (<|w|^2> - |<w>|^2) over the normalised weights:
// 1 for perfectly correlated weights and 0 for independent ones; for forces <f> = 1, so
// C = (F - 1)/(<f^2> - 1); for velocity fluctuations C = F / <|C|^2>.
//
// Errors: delete-one-group jackknife. With two or more frames the groups are the frames; with
// one frame the points are split into `groups` pseudo-random groups and a replicate drops every
// pair touching its group. This accounts for pair terms sharing points but not for spatial
// correlation between disjoint pairs, so use several well-separated frames for quoted errors.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "core/data/Domain.hpp"

namespace grainbridge::extract::statistics {

enum class FrameNormalisation {
  None,          // weights used as given
  DivideByMean,  // scalar weights only: w / <w>_frame (normalised contact forces)
  SubtractMean,  // w - <w>_frame (velocity fluctuations)
};

struct CorrelationOptions {
  double binWidth = 0.0;  // dr, in the frame's length unit
  double rMax = 0.0;      // pairs with r >= rMax are not counted; bins = ceil(rMax / dr)
  int groups = 16;        // jackknife groups within a frame (used when only one frame is added)
};

struct CorrelationFunction {
  std::vector<double> rLo, rHi, r;  // bin edges and centres
  std::vector<double> pairs;        // pair count per bin over all frames
  std::vector<double> value;        // F(r) of the normalised weights; NaN where a bin has no pairs
  std::vector<double> error;        // jackknife standard error of F(r); NaN when undefined
  std::vector<double> normalised;   // C(r)
  std::vector<double> normalisedError;
  double mean = 0.0;        // |<w>| of the normalised weights (1 for forces, 0 for fluctuations)
  double meanSquare = 0.0;  // <|w|^2> of the normalised weights
  std::size_t points = 0, frames = 0;
  std::string resampling;  // "frames" or "point groups"
  // Jackknife replicates of C(r), one per deleted group, for errors of derived quantities such
  // as correlation lengths (see CorrelationLength.hpp).
  std::vector<std::vector<double>> replicateNormalised;
  [[nodiscard]] std::size_t bins() const { return r.size(); }
};

class CorrelationAccumulator {
 public:
  // Throws grainbridge::Error naming `what` for a non-positive bin width or r_max, or fewer
  // than two jackknife groups.
  CorrelationAccumulator(const CorrelationOptions& options, FrameNormalisation normalisation, std::string what);

  // One frame of scalar weights (product w_i w_j).
  void add(const core::data::Domain& domain, std::span<const Vec3> positions, std::span<const double> weights);
  // One frame of vector weights (dot product w_i . w_j). Not with DivideByMean.
  void add(const core::data::Domain& domain, std::span<const Vec3> positions, std::span<const Vec3> weights);

  // Throws grainbridge::Error if nothing was added or the weights have no spread.
  [[nodiscard]] CorrelationFunction result() const;

 private:
  // Sums over a set of pairs and points of one frame, raw weights: per bin sum w_i . w_j,
  // sum (w_i + w_j) (needed to re-centre) and the pair count; the points' sum w, sum |w|^2, n.
  struct RawSums {
    std::vector<double> product, count;
    std::vector<Vec3> pairSum;
    Vec3 sumW = Vec3::Zero();
    double sumW2 = 0.0, points = 0.0;
    void resize(std::size_t bins);
    RawSums& operator-=(const RawSums& o);
  };
  // The same sums after the frame normalisation; these add across frames.
  struct Sums {
    std::vector<double> product, count;
    Vec3 sumW = Vec3::Zero();
    double sumW2 = 0.0, points = 0.0;
    Sums& operator+=(const Sums& o);
    Sums& operator-=(const Sums& o);
  };
  void addVectors(const core::data::Domain& domain, std::span<const Vec3> positions, std::span<const Vec3> weights,
                  bool scalar);
  [[nodiscard]] Sums normalise(const RawSums& raw) const;
  [[nodiscard]] std::vector<double> correlation(const Sums& s) const;
  [[nodiscard]] std::vector<double> normalisedCorrelation(const Sums& s) const;

  CorrelationOptions options_;
  FrameNormalisation normalisation_;
  std::string what_;
  std::size_t bins_ = 0;
  int kind_ = 0;  // 0 nothing yet, 1 scalar, 2 vector
  std::vector<Sums> frames_;
  RawSums firstFrame_;
  std::vector<RawSums> groupsOfFirstFrame_;  // pairs touching group g, points of group g
};

}  // namespace grainbridge::extract::statistics
