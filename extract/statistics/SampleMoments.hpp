#pragma once
// Central moments of a one-dimensional sample with delta-method standard errors: the variance,
// skewness and kurtosis <C^4>/<C^2>^2 of a velocity component (Section 8.2.1.1: how far the
// single-particle distribution is from the Maxwellian assumed by KTGF, for which kurtosis = 3).
// Moments are about the sample mean with 1/N normalisation. Errors treat the samples as
// independent and include the effect of estimating the mean: each estimator's influence
// function psi (e.g. for m4: c^4 - m4 - 4 m3 c) gives var = sum psi_i^2 / N^2, which for a
// Gaussian reproduces var(kurtosis) = 24/N.
#include <cstddef>
#include <span>
#include <string>

namespace grainbridge::extract::statistics {

struct SampleMoments {
  std::size_t samples = 0;
  double mean = 0.0;
  double variance = 0.0, varianceError = 0.0;  // m2 = <c^2>
  double skewness = 0.0, skewnessError = 0.0;  // m3 / m2^{3/2}
  double kurtosis = 0.0, kurtosisError = 0.0;  // m4 / m2^2 (Gaussian 3, uniform 1.8)
};

// Throws grainbridge::Error naming `what` for fewer than two samples, a non-finite sample or a
// sample without spread.
SampleMoments sampleMoments(std::span<const double> x, const std::string& what = "sample moments");

}  // namespace grainbridge::extract::statistics
