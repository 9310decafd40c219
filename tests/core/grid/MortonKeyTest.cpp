// Morton keys: bit interleaving checked against a bit-by-bit reference, and the locality that
// is the reason to use them.
#include "core/grid/MortonKey.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

using namespace grainbridge;
using grainbridge::grid::mortonKey;

namespace {
std::uint64_t interleaveBitByBit(const Vec3i& c) {
  std::uint64_t key = 0;
  for (int bit = 0; bit < 21; ++bit) {
    for (int a = 0; a < 3; ++a) {
      key |= static_cast<std::uint64_t>((c[a] >> bit) & 1) << (3 * bit + a);
    }
  }
  return key;
}
}  // namespace

TEST(MortonKey, InterleavesTheBitsOfXYZ) {
  EXPECT_EQ(mortonKey(Vec3i(0, 0, 0)), 0u);
  EXPECT_EQ(mortonKey(Vec3i(1, 0, 0)), 1u);
  EXPECT_EQ(mortonKey(Vec3i(0, 1, 0)), 2u);
  EXPECT_EQ(mortonKey(Vec3i(0, 0, 1)), 4u);
  EXPECT_EQ(mortonKey(Vec3i(2, 0, 0)), 8u);
  const int top = (1 << 21) - 1;
  EXPECT_EQ(mortonKey(Vec3i(top, top, top)), (std::uint64_t{1} << 63) - 1);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> index(0, top);
  for (int k = 0; k < 1000; ++k) {
    const Vec3i c(index(rng), index(rng), index(rng));
    ASSERT_EQ(mortonKey(c), interleaveBitByBit(c)) << c.transpose();
  }
}

TEST(MortonKey, EveryAlignedBlockOfCellsIsContiguousInOrder) {
  // In a 16^3 grid sorted by key, each aligned 2^k block occupies one run of 8^k keys: the
  // z neighbours of a cell are never more than a block away, unlike row-major order.
  const int n = 16;
  std::vector<std::pair<std::uint64_t, Vec3i>> cells;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) cells.emplace_back(mortonKey(Vec3i(x, y, z)), Vec3i(x, y, z));
  std::sort(cells.begin(), cells.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (int block : {2, 4, 8}) {
    const std::size_t run = static_cast<std::size_t>(block * block * block);
    for (std::size_t start = 0; start < cells.size(); start += run) {
      const Vec3i corner = cells[start].second / block;
      for (std::size_t k = start; k < start + run; ++k) {
        ASSERT_EQ(cells[k].second / block, corner) << "block " << block << " at key " << cells[k].first;
      }
    }
  }
}
