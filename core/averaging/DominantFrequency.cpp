#include "core/averaging/DominantFrequency.hpp"

#include <cmath>
#include <complex>
#include <numeric>
#include <unsupported/Eigen/FFT>

namespace grainbridge::core::averaging {

std::optional<Spectrum> dominantFrequency(const std::vector<double>& samples, double dt) {
  const std::size_t n = samples.size();
  if (n < 8 || !(dt > 0.0)) return std::nullopt;
  const double mean = std::accumulate(samples.begin(), samples.end(), 0.0) / static_cast<double>(n);
  std::vector<double> centred(n);
  for (std::size_t i = 0; i < n; ++i) centred[i] = samples[i] - mean;
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, centred);
  // One-sided amplitudes of the bins 1 .. n/2.
  std::vector<double> amplitude(n / 2 + 1, 0.0);
  for (std::size_t k = 1; k <= n / 2; ++k) amplitude[k] = 2.0 * std::abs(spectrum[k]) / static_cast<double>(n);
  std::size_t peak = 1;
  for (std::size_t k = 2; k <= n / 2; ++k) {
    if (amplitude[k] > amplitude[peak]) peak = k;
  }
  if (!(amplitude[peak] > 0.0)) return std::nullopt;
  double offset = 0.0;
  if (peak > 1 && peak < n / 2) {
    const double a = amplitude[peak - 1], b = amplitude[peak], c = amplitude[peak + 1];
    const double curvature = a - 2.0 * b + c;
    if (curvature < 0.0) offset = 0.5 * (a - c) / curvature;
  }
  Spectrum s;
  s.resolution = 1.0 / (static_cast<double>(n) * dt);
  s.frequency = (static_cast<double>(peak) + offset) * s.resolution;
  s.amplitude = amplitude[peak];
  return s;
}

}  // namespace grainbridge::core::averaging
