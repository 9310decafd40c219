// core/averaging/TimeBlocks: 1 s means of a series sampled every 0.1 s, as the segregation
// percentage is against the experiment's 1 s values.
#include "core/averaging/TimeBlocks.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "core/Error.hpp"

using namespace grainbridge;
using namespace grainbridge::core::averaging;

TEST(TimeBlocks, SamplesAtTheBlockEndCountInThatBlock) {
  std::vector<double> times, values;
  for (int k = 1; k <= 25; ++k) {
    times.push_back(0.1 * k);  // 0.1, 0.2, ... 2.5, with the round-off of 0.1 * k
    values.push_back(k <= 10 ? 1.0 : (k <= 20 ? static_cast<double>(k) : -1.0));
  }
  const auto blocks = timeBlockMeans(times, values, 1.0);
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_EQ(blocks[0].samples, 10u);
  EXPECT_DOUBLE_EQ(blocks[0].mean, 1.0);
  EXPECT_EQ(blocks[1].samples, 10u);
  EXPECT_DOUBLE_EQ(blocks[1].mean, 15.5);  // the mean of 11..20
  EXPECT_DOUBLE_EQ(blocks[1].start, 1.0);
  EXPECT_DOUBLE_EQ(blocks[1].end, 2.0);
  EXPECT_EQ(blocks[2].samples, 5u);  // a partial last block says how many samples it has
}

TEST(TimeBlocks, ATimeZeroSampleFallsInNoBlockAndBadInputIsRefused) {
  const std::vector<double> t{0.0, 0.5}, v{7.0, 3.0};
  const auto blocks = timeBlockMeans(t, v, 1.0);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_DOUBLE_EQ(blocks[0].mean, 3.0);
  EXPECT_THROW((void)timeBlockMeans(t, std::vector<double>{1.0}, 1.0), Error);
  EXPECT_THROW((void)timeBlockMeans(t, v, 0.0), Error);
}
