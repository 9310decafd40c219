#pragma once
// Particle-wall contacts of one frame. Walls are not particles (no id), so they get their
// own list: wall stress and the wall-side part of Eq. 2.3 need the point and the force.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/Types.hpp"

namespace grainbridge::core::data {

struct WallContactList {
  std::vector<std::int64_t> particle;  // global particle id
  std::vector<std::int32_t> wall;      // index into Domain::walls
  std::vector<Vec3> point;
  std::vector<Vec3> forceNormal, forceTangential;  // force on the particle from the wall

  [[nodiscard]] std::size_t size() const { return particle.size(); }
  // Throws grainbridge::Error naming the array of the wrong length or the wall index out of
  // [0, wallCount).
  void validate(std::size_t wallCount) const;

  bool operator==(const WallContactList&) const = default;
};

}  // namespace grainbridge::core::data
