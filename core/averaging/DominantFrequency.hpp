#pragma once
// The dominant frequency of an evenly sampled signal (a pressure drop against time, Fig. 7.3):
// the frequency of the largest amplitude of its discrete Fourier transform after the mean is
// removed, by Eigen's FFT (kissfft). The resolution is one bin, 1 / (N dt); the value is the
// bin's centre, refined by a parabola through the peak and its neighbours' amplitudes.
#include <optional>
#include <vector>

namespace grainbridge::core::averaging {

struct Spectrum {
  double frequency = 0.0;   // dominant frequency [1/time unit of dt]
  double amplitude = 0.0;   // its one-sided amplitude (a sine of amplitude A gives about A)
  double resolution = 0.0;  // 1 / (N dt)
};

// None for fewer than 8 samples, dt <= 0 or a constant signal.
[[nodiscard]] std::optional<Spectrum> dominantFrequency(const std::vector<double>& samples, double dt);

}  // namespace grainbridge::core::averaging
