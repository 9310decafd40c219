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

// The same of a signal sampled at `times` (increasing, one per sample): the spacing is the
// samples' own, never a nominal interval (rows that fall 0.0125 s apart read as 0.0142 s apart
// move every frequency by the ratio of the two). Times even to 1e-6 of a spacing are taken as
// they are, dt = (t_last - t_first) / (n - 1); uneven ones are first interpolated linearly onto n
// even times over the same span. None also when the times are not increasing or their count is
// not the samples'.
[[nodiscard]] std::optional<Spectrum> dominantFrequency(const std::vector<double>& times,
                                                        const std::vector<double>& samples);

}  // namespace grainbridge::core::averaging
