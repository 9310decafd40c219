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

std::optional<Spectrum> dominantFrequency(const std::vector<double>& times, const std::vector<double>& samples) {
  const std::size_t n = samples.size();
  if (n < 8 || times.size() != n) return std::nullopt;
  const double span = times.back() - times.front();
  const double dt = span / static_cast<double>(n - 1);
  if (!(dt > 0.0)) return std::nullopt;
  bool even = true;
  for (std::size_t i = 1; i < n; ++i) {
    const double step = times[i] - times[i - 1];
    if (!(step > 0.0)) return std::nullopt;
    if (std::abs(step - dt) > 1e-6 * dt) even = false;
  }
  if (even) return dominantFrequency(samples, dt);
  // Linear interpolation onto the even grid t_0 + i dt: its error is second order in the spacing,
  // far below the one-bin resolution for a signal sampled several times per period.
  std::vector<double> resampled(n);
  std::size_t j = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = i + 1 == n ? times.back() : times.front() + static_cast<double>(i) * dt;
    while (j + 2 < n && times[j + 1] < t) ++j;
    const double w = (t - times[j]) / (times[j + 1] - times[j]);
    resampled[i] = (1.0 - w) * samples[j] + w * samples[j + 1];
  }
  return dominantFrequency(resampled, dt);
}

}  // namespace grainbridge::core::averaging
