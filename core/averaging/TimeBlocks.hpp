#pragma once
// Means of a sampled series over consecutive time blocks [k L, (k + 1) L), as an experiment that
// reports one value per interval does (Goldschmidt's segregation data: 1 s means, reference line
// ~1285). A sample at time t belongs to the block whose interval holds t - L * 1e-9 (an output
// time at the block's end, up to round-off, counts in that block), so t = 0 falls in no block.
#include <cstddef>
#include <span>
#include <vector>

namespace grainbridge::core::averaging {

struct TimeBlock {
  double start = 0.0, end = 0.0;
  double mean = 0.0;
  std::size_t samples = 0;
};

// The blocks that hold at least one sample, in time order. Throws grainbridge::Error when the
// spans differ in length, the length is not positive, or a time or value is not finite.
std::vector<TimeBlock> timeBlockMeans(std::span<const double> times, std::span<const double> values, double length);

}  // namespace grainbridge::core::averaging
