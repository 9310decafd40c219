#pragma once
// The simulation box a particle frame lives in. Extract needs it to undo periodic and
// Lees-Edwards images (Eq. 2.3 sums over branch vectors across the boundary) and to know
// the wall positions at the time of the frame, so it is stored with every frame rather
// than once per run: walls move and the Lees-Edwards offset grows with time.
#include <array>
#include <string>
#include <vector>

#include "core/Types.hpp"

namespace grainbridge::core::data {

struct Wall {
  std::string kind;                // "plane" or "cylinder"
  Vec3 origin = Vec3::Zero();      // current point on the plane, or on the cylinder axis
  Vec3 direction = Vec3::UnitZ();  // plane normal, or cylinder axis (unit vector)
  double radius = 0.0;             // cylinder only; 0 for a plane
  Vec3 velocity = Vec3::Zero();    // current wall velocity

  bool operator==(const Wall&) const = default;
};

struct Domain {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
  std::array<bool, 3> periodic{false, false, false};
  // Lees-Edwards: the image above the box in y is shifted by this offset in x and moves
  // with shear rate * box height (the simple-shear cases of Chapter 6).
  double leesEdwardsOffset = 0.0;
  double leesEdwardsShearRate = 0.0;
  std::vector<Wall> walls;

  bool operator==(const Domain&) const = default;
};

}  // namespace grainbridge::core::data
