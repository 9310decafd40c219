// Blocking (Flyvbjerg-Petersen) standard errors: an AR(1) series with correlation 0.9 has the
// true standard error of its mean sqrt((1 + rho) / (1 - rho) / n) = 4.4 times the naive one, which
// the blocking estimate recovers; independent samples keep the naive error; a short series gets the
// plain standard error, flagged as such.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/Error.hpp"
#include "core/averaging/BlockAverage.hpp"

using namespace grainbridge;
using namespace grainbridge::core::averaging;

namespace {
std::vector<double> ar1(std::size_t n, double rho, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  std::vector<double> x(n);
  double v = g(rng);
  for (auto& xi : x) {
    v = rho * v + std::sqrt(1 - rho * rho) * g(rng);
    xi = 5.0 + v;
  }
  return x;
}
}  // namespace

TEST(BlockAverage, RecoversTheStandardErrorOfACorrelatedSeries) {
  const std::size_t n = 1 << 15;
  const double rho = 0.9;
  const double truth = std::sqrt((1 + rho) / (1 - rho) / static_cast<double>(n));
  for (std::uint64_t seed : {1, 2, 3}) {
    const auto b = blockAverage(ar1(n, rho, seed));
    std::printf("AR(1) seed %d: SE %.5f +- %.5f (true %.5f, naive %.5f), block %zu\n", static_cast<int>(seed),
                b.standardError, b.standardErrorUncertainty, truth, b.standardErrorByLevel.front(), b.blockSize);
    EXPECT_EQ(b.method, BlockAverage::Method::Blocking);
    EXPECT_TRUE(b.plateauReached);
    EXPECT_NEAR(b.standardError / truth, 1.0, 0.2);
    EXPECT_NEAR(b.mean, 5.0, 5 * truth);
    EXPECT_LT(b.standardErrorByLevel.front(), 0.3 * truth);  // the naive error is far too small
  }
}

TEST(BlockAverage, IndependentSamplesKeepTheNaiveError) {
  const auto x = ar1(4096, 0.0, 4);
  const auto b = blockAverage(x);
  EXPECT_TRUE(b.plateauReached);
  EXPECT_NEAR(b.standardError * std::sqrt(4096.0), 1.0, 0.15);
}

TEST(BlockAverage, FewFramesGiveThePlainStandardErrorAndSaySo) {
  const std::vector<double> x{1.0, 2.0, 4.0, 3.0};
  const auto b = blockAverage(x);
  EXPECT_EQ(b.method, BlockAverage::Method::PlainFewSamples);
  EXPECT_DOUBLE_EQ(b.mean, 2.5);
  EXPECT_NEAR(b.standardError, std::sqrt(1.25 / 3.0), 1e-15);  // sqrt(var / (n - 1))
  EXPECT_THROW(blockAverage(std::vector<double>{}), Error);
  EXPECT_THROW(blockAverage(std::vector<double>{1.0, NAN}), Error);
}

TEST(BlockAverage, CellsAreAveragedOneByOne) {
  const std::vector<std::vector<double>> frames{{1.0, 10.0}, {3.0, 10.0}};
  const auto cells = blockAverageCells(frames);
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_DOUBLE_EQ(cells[0].mean, 2.0);
  EXPECT_DOUBLE_EQ(cells[1].standardError, 0.0);
  EXPECT_THROW(blockAverageCells({{1.0}, {1.0, 2.0}}), Error);
}

// Issue 63: a level of two blocks has one degree of freedom, and its error can come out near zero
// by chance, which then meets the Lee et al. criterion. A strongly correlated series of 64 frames
// (a slow ramp and back: the two halves have the same mean) gives levels that rise, then nothing
// at two blocks; the reported error must be one of the levels with at least four blocks.
TEST(BlockAverage, ALevelOfFewerThanFourBlocksIsNeverReported) {
  std::vector<double> x;
  for (int i = 0; i < 32; ++i) x.push_back(1.0 + 0.01 * i);
  for (int i = 0; i < 32; ++i) x.push_back(1.0 + 0.01 * i);  // the same ramp again: equal halves
  const auto b = blockAverage(x);
  ASSERT_GE(b.standardErrorByLevel.size(), 6u);
  EXPECT_LT(b.standardErrorByLevel.back(), 1e-12);  // the two blocks' means are equal
  EXPECT_GT(b.standardError, 0.5 * b.standardErrorByLevel[1]);
  EXPECT_LE(b.blockSize, 16u);  // 64 / 16 = 4 blocks at most
}
