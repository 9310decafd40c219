#pragma once
// Correlation lengths from a normalised correlation C(r) (PairCorrelation.hpp). The reference
// reads its force correlation length off Fig. 6.12(b) ("peaks around r = d0 and dies out after
// 3 d0") without a definition, so two are offered:
//
//  decayLength: from the peak r_p (the bin centre with the largest C among bins with at least
//    minPairs pairs) to r_e, the first r beyond it where C falls to C(r_p)/e, linearly
//    interpolated between bin centres: xi = r_e - r_p. Measured from the peak because the force
//    correlation rises to a peak near d0 (contacts closer than ~d0/2 do not exist), and relative
//    to the peak because the normalised force correlation never approaches 1. For
//    C = e^{-r/xi} it returns xi up to the interpolation error, O((dr/xi)^2).
//    Error: the jackknife spread of xi over the replicates of C (frames or point groups).
//
//  exponentialLength: a Levenberg-Marquardt fit of C(r) = A e^{-(r - r_p)/xi} over bins from
//    r_p to rFitMax, weighted by the jackknife errors of C. Error: the jackknife spread of the
//    fitted xi over the replicates of C. The covariance error (J^T W J)^{-1} chi^2/dof is kept
//    for reference only: the bins of C share points and are strongly correlated, so it is
//    several times too small (about 5x on an Ornstein-Uhlenbeck test field).
#include <cstddef>
#include <limits>

#include "extract/statistics/PairCorrelation.hpp"

namespace grainbridge::extract::statistics {

struct CorrelationLengthOptions {
  double minPairs = 100.0;  // bins with fewer pairs are ignored (their C is too noisy to be a peak)
  double rFitMax = std::numeric_limits<double>::infinity();  // exponential fit only
};

struct CorrelationLength {
  double length = 0.0;               // xi = r_e - r_p, in the correlation's length unit
  double error = 0.0;                // jackknife standard error (NaN if a replicate had no crossing)
  double rPeak = 0.0;                // r_p
  double rCross = 0.0;               // r_e
  double peak = 0.0;                 // C(r_p)
  std::size_t replicates = 0;        // jackknife replicates with a crossing
  std::size_t failedReplicates = 0;  // replicates without one
};

struct ExponentialLength {
  double length = 0.0, lengthError = 0.0;        // xi, jackknife error (NaN if a replicate fit failed)
  double amplitude = 0.0, amplitudeError = 0.0;  // A = C at r_p, jackknife error
  double lengthErrorCovariance = 0.0;            // from (J^T W J)^{-1} chi^2/dof; too small, see above
  double rPeak = 0.0, rEnd = 0.0;                // fitted range of bin centres
  double chi2PerDof = 0.0;
  std::size_t binsUsed = 0;
};

// Throws grainbridge::Error when no bin has enough pairs, the peak is not positive, or C never
// falls to C(r_p)/e within r_max (then r_max is too small for this correlation).
CorrelationLength decayLength(const CorrelationFunction& c, const CorrelationLengthOptions& options = {});
// Throws grainbridge::Error when fewer than three usable bins lie in the range.
ExponentialLength exponentialLength(const CorrelationFunction& c, const CorrelationLengthOptions& options = {});

}  // namespace grainbridge::extract::statistics
