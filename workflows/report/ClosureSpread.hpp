#pragma once
// How much the DEM closures' statistical error moves a continuum run's output (issue 31): the
// spread of the output over the run's closure samples (workflows/stages/ClosureSamples.hpp), and
// the share of it each table quantity carries.
//
// Each sample's output is a time average with its own statistical error (the bed's fluctuations),
// so the scatter over samples holds that noise too: the closures' variance is the samples'
// variance less the mean of their squared errors (zero when the noise accounts for all of it,
// that is when the closures' effect is not resolved). The spread is that over the joint samples
// (every table drawn) when there are at least two; otherwise the root sum of squares of the
// one-at-a-time spreads, which assumes the output responds to each quantity's error
// independently and linearly (the draws are independent, so for a linear response the two
// agree). A quantity's share is its one-at-a-time variance over the sum of them: which quantity
// dominates, the nominal run's other tables held.
#include <string>
#include <vector>

namespace grainbridge::workflows::report {

// The outputs of a bed run the samples are read for (summary keys; pressure_drop stands for the
// compared tap's dp_<tap>) and the table quantities a share is given of.
inline const std::vector<std::string> kClosureSampledOutputs = {"mean_height", "pressure_drop",
                                                                "segregation_percentage"};
inline const std::vector<std::string> kClosureSampledQuantities = {"p_theta", "eta_theta", "j_theta"};

// One closure sample's output: what it drew ("all", or the one quantity drawn) and its value.
struct ClosureSampleValue {
  std::string perturbed;
  double value = 0.0;
  double error = 0.0;  // its own statistical (block-averaging) error
};

struct QuantitySpread {
  std::string quantity;  // p_theta, eta_theta, j_theta
  int samples = 0;
  double spread = 0.0;  // over its one-at-a-time samples, less their own noise
  double share = 0.0;   // spread^2 / sum of the quantities' spread^2 (0 when every spread is 0)
};

struct ClosureSpread {
  int jointSamples = 0;
  double spread = 0.0;                     // the output's standard deviation from the closures
  double scatter = 0.0;                    // the samples' standard deviation as measured (noise included)
  bool fromJoint = false;                  // over joint samples, or the one-at-a-time root sum of squares
  std::vector<QuantitySpread> quantities;  // in the order the samples first name them

  // The quantity with the largest share, or "" without one-at-a-time samples.
  [[nodiscard]] std::string dominant() const;
};

// Throws grainbridge::Error when the samples give no spread: fewer than two joint samples and no
// quantity with two one-at-a-time samples.
[[nodiscard]] ClosureSpread closureSpread(const std::vector<ClosureSampleValue>& samples);

}  // namespace grainbridge::workflows::report
