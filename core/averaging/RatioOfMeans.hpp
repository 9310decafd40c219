#pragma once
// The ratio of two time averages, <a> / <b>, with a standard error that keeps their correlation:
// the delta method on the frame series, d_k = (a_k - R b_k) / <b>, whose mean is zero and whose
// block-averaging error (BlockAverage.hpp) is the error of R to first order. Shear stress over
// pressure is the case it is for: both rise and fall together with the frames' collisions, so
// adding their relative errors in quadrature would overstate the error of their ratio.
#include <span>

namespace grainbridge::core::averaging {

struct Ratio {
  double value = 0.0;
  double standardError = 0.0;
};

// Throws grainbridge::Error for series of different lengths, an empty or non-finite one, or a
// zero mean of b.
Ratio ratioOfMeans(std::span<const double> a, std::span<const double> b);

}  // namespace grainbridge::core::averaging
