// The ratio of two time averages keeps their correlation (RatioOfMeans.hpp): stress over
// pressure of a sheared box, whose frames rise and fall together.
#include "core/averaging/RatioOfMeans.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/Error.hpp"
#include "core/averaging/BlockAverage.hpp"

namespace grainbridge::core::averaging {
namespace {

TEST(RatioOfMeans, ProportionalSeriesHaveAnExactRatio) {
  // a = 0.3 b frame by frame: the ratio is known without error, although each mean has one
  // (quadrature of the relative errors would say 0.3 sqrt(2) x their relative error).
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.2);
  std::vector<double> a, b;
  for (int k = 0; k < 256; ++k) {
    b.push_back(1.0 + noise(rng));
    a.push_back(0.3 * b.back());
  }
  const Ratio r = ratioOfMeans(a, b);
  EXPECT_NEAR(r.value, 0.3, 1e-14);
  EXPECT_LT(r.standardError, 1e-14);
  EXPECT_GT(blockAverage(b).standardError, 1e-3);
}

TEST(RatioOfMeans, ConstantDenominatorGivesTheNumeratorsError) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 0.5);
  std::vector<double> a, b(300, 4.0);
  for (int k = 0; k < 300; ++k) a.push_back(2.0 + noise(rng));
  const Ratio r = ratioOfMeans(a, b);
  const BlockAverage ba = blockAverage(a);
  EXPECT_NEAR(r.value, ba.mean / 4.0, 1e-14);
  EXPECT_NEAR(r.standardError, ba.standardError / 4.0, 1e-14);
}

TEST(RatioOfMeans, IndependentSeriesAddRelativeErrorsInQuadrature) {
  // Independent noise: the delta method's error agrees with the quadrature estimate (within the
  // error estimates' own scatter).
  std::mt19937_64 rng(3);
  std::normal_distribution<double> na(0.0, 0.1), nb(0.0, 0.2);
  std::vector<double> a, b;
  for (int k = 0; k < 4096; ++k) {
    a.push_back(1.0 + na(rng));
    b.push_back(2.0 + nb(rng));
  }
  const Ratio r = ratioOfMeans(a, b);
  const BlockAverage ba = blockAverage(a), bb = blockAverage(b);
  const double quadrature = r.value * std::hypot(ba.standardError / ba.mean, bb.standardError / bb.mean);
  EXPECT_NEAR(r.standardError / quadrature, 1.0, 0.15);
}

TEST(RatioOfMeans, RefusesMismatchedOrZeroDenominators) {
  EXPECT_THROW((void)ratioOfMeans(std::vector<double>{1, 2}, std::vector<double>{1}), Error);
  EXPECT_THROW((void)ratioOfMeans(std::vector<double>{1, 2}, std::vector<double>{1, -1}), Error);
}

}  // namespace
}  // namespace grainbridge::core::averaging
