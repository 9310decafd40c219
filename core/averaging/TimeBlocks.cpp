#include "core/averaging/TimeBlocks.hpp"

#include <cmath>
#include <map>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::core::averaging {

std::vector<TimeBlock> timeBlockMeans(std::span<const double> times, std::span<const double> values, double length) {
  if (times.size() != values.size())
    throw Error("time blocks: " + std::to_string(times.size()) + " times for " + std::to_string(values.size()) +
                " values");
  if (!(length > 0.0) || !std::isfinite(length)) throw Error("time blocks: the block length must be positive");
  std::map<long long, TimeBlock> blocks;
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k]) || !std::isfinite(values[k]))
      throw Error("time blocks: sample " + std::to_string(k) + " is not finite");
    const double shifted = times[k] - 1e-9 * length;
    if (shifted < 0.0) continue;
    const auto index = static_cast<long long>(std::floor(shifted / length));
    TimeBlock& b = blocks[index];
    b.start = static_cast<double>(index) * length;
    b.end = b.start + length;
    b.mean += values[k];
    ++b.samples;
  }
  std::vector<TimeBlock> out;
  for (auto& [index, b] : blocks) {
    b.mean /= static_cast<double>(b.samples);
    out.push_back(b);
  }
  return out;
}

}  // namespace grainbridge::core::averaging
