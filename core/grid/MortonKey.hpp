#pragma once
// Morton (Z-order) key of a cell: the bits of its x, y and z indices interleaved, so cells close
// in space get keys close in order in all three directions (row-major order keeps only x
// neighbours close). Used to sort particles for cache locality.
#include <cstdint>

#include "core/Types.hpp"

namespace grainbridge::grid {

// Spreads the low 21 bits of v so that bit k lands at bit 3k.
constexpr std::uint64_t spreadBitsBy3(std::uint64_t v) {
  v &= 0x1fffffULL;
  v = (v | (v << 32)) & 0x1f00000000ffffULL;
  v = (v | (v << 16)) & 0x1f0000ff0000ffULL;
  v = (v | (v << 8)) & 0x100f00f00f00f00fULL;
  v = (v | (v << 4)) & 0x10c30c30c30c30c3ULL;
  v = (v | (v << 2)) & 0x1249249249249249ULL;
  return v;
}

// Cell indices must be in [0, 2^21); x takes the lowest bit of each triple.
inline std::uint64_t mortonKey(const Vec3i& cell) {
  return spreadBitsBy3(static_cast<std::uint64_t>(cell[0])) |
         (spreadBitsBy3(static_cast<std::uint64_t>(cell[1])) << 1) |
         (spreadBitsBy3(static_cast<std::uint64_t>(cell[2])) << 2);
}

}  // namespace grainbridge::grid
