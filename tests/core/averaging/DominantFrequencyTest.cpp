// The dominant frequency of a sampled signal (the pressure-drop fluctuation of Fig. 7.3).
#include "core/averaging/DominantFrequency.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using grainbridge::core::averaging::dominantFrequency;

TEST(DominantFrequency, FindsTheStrongestSineAboveAMeanAndAWeakerOne) {
  // 1000 samples of 10 ms: 2.37 Hz at amplitude 30 (between bins of 0.1 Hz) over a mean of
  // 2000, plus 7.9 Hz at amplitude 10.
  std::vector<double> p;
  for (int i = 0; i < 1000; ++i) {
    const double t = 0.01 * i;
    p.push_back(2000.0 + 30.0 * std::sin(2.0 * std::numbers::pi * 2.37 * t) +
                10.0 * std::cos(2.0 * std::numbers::pi * 7.9 * t));
  }
  const auto s = dominantFrequency(p, 0.01);
  ASSERT_TRUE(s.has_value());
  EXPECT_DOUBLE_EQ(s->resolution, 0.1);
  EXPECT_NEAR(s->frequency, 2.37, 0.5 * s->resolution);
  EXPECT_GT(s->amplitude, 20.0);  // a sine between bins loses part of its amplitude to neighbours
  EXPECT_LT(s->amplitude, 31.0);
}

TEST(DominantFrequency, HasNoAnswerForAConstantOrTooShortSignal) {
  EXPECT_FALSE(dominantFrequency(std::vector<double>(100, 5.0), 0.01).has_value());
  EXPECT_FALSE(dominantFrequency({1.0, 2.0, 1.0}, 0.01).has_value());
  EXPECT_FALSE(dominantFrequency(std::vector<double>(100, 5.0), 0.0).has_value());
}

namespace {

// A pressure drop of mean 2000 Pa fluctuating at `f` with amplitude 300 Pa, sampled at `times`.
std::vector<double> sineAt(const std::vector<double>& times, double f) {
  std::vector<double> p;
  for (double t : times) p.push_back(2000.0 + 300.0 * std::sin(2.0 * std::numbers::pi * f * t + 0.3));
  return p;
}

}  // namespace

// Rows 0.0125 s apart that a stage takes for its nominal 0.0142 s (issue 54: a tfdem run's rows
// spread evenly over the run, not output_interval apart): the nominal interval moves the
// frequency by the spacing ratio, 12 %; the rows' own times give it to a quarter of a bin
// (0.025 Hz of 2.37 Hz, 1 %).
TEST(DominantFrequency, OfEvenRowsIsTakenFromTheirTimesNotANominalInterval) {
  std::vector<double> times;
  for (int i = 0; i < 800; ++i) times.push_back(0.5 + 0.0125 * i);
  const double f = 2.37;
  const auto s = dominantFrequency(times, sineAt(times, f));
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->resolution, 0.1, 1e-12);
  EXPECT_NEAR(s->frequency, f, 0.25 * s->resolution);
  // Between bins a sine keeps at least 2/pi of its amplitude in its bin (the rest goes to the
  // neighbours): 191 of 300 Pa.
  EXPECT_GT(s->amplitude, 0.6 * 300.0);
  EXPECT_LT(s->amplitude, 1.02 * 300.0);
  const auto nominal = dominantFrequency(sineAt(times, f), 0.0142);
  ASSERT_TRUE(nominal.has_value());
  EXPECT_NEAR(nominal->frequency / s->frequency, 0.0125 / 0.0142, 1e-9);
}

// Rows 100 and 101 gas steps of 1.42e-4 s apart by turns, and rows with a random spacing of 88 to
// 101 gas steps: the uneven times are interpolated onto even ones, and each sine's frequency
// comes back to a quarter of a bin.
TEST(DominantFrequency, OfUnevenRowsComesBackToAQuarterOfABin) {
  std::vector<double> alternating{0.0};
  for (int i = 0; i < 799; ++i) alternating.push_back(alternating.back() + (i % 2 == 0 ? 100 : 101) * 1.42e-4);
  std::vector<double> random{0.0};
  std::uint32_t state = 12345;  // a fixed LCG: the same spacings on every platform
  for (int i = 0; i < 799; ++i) {
    state = state * 1664525u + 1013904223u;
    random.push_back(random.back() + static_cast<double>(88 + (state >> 16) % 14) * 1.42e-4);
  }
  for (const auto* times : {&alternating, &random}) {
    for (const double f : {1.8, 2.37, 3.1, 7.9}) {
      const auto s = dominantFrequency(*times, sineAt(*times, f));
      ASSERT_TRUE(s.has_value());
      const double span = times->back() - times->front();
      EXPECT_NEAR(s->resolution, 799.0 / (800.0 * span), 1e-12);
      EXPECT_NEAR(s->frequency, f, 0.25 * s->resolution) << "f = " << f << " Hz, rows over " << span << " s";
      EXPECT_GT(s->amplitude, 0.6 * 300.0) << "f = " << f << " Hz";  // 2/pi of it between bins
      EXPECT_LT(s->amplitude, 1.02 * 300.0) << "f = " << f << " Hz";
    }
  }
}

TEST(DominantFrequency, OfTimesHasNoAnswerForTooFewOrUnorderedTimes) {
  std::vector<double> times;
  for (int i = 0; i < 20; ++i) times.push_back(0.01 * i);
  EXPECT_TRUE(dominantFrequency(times, sineAt(times, 10.0)).has_value());
  EXPECT_FALSE(dominantFrequency(std::vector<double>(times.begin(), times.begin() + 5),
                                 sineAt(std::vector<double>(times.begin(), times.begin() + 5), 10.0))
                   .has_value());
  EXPECT_FALSE(dominantFrequency(times, std::vector<double>(19, 1.0)).has_value());
  auto unordered = times;
  std::swap(unordered[3], unordered[4]);
  EXPECT_FALSE(dominantFrequency(unordered, sineAt(unordered, 10.0)).has_value());
}
