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
