#pragma once
// Minimum-image displacements in a frame's box (core/data/Domain.hpp): periodic axes wrap, and
// with Lees-Edwards the image above the box in y is shifted by +leesEdwardsOffset in x (the
// engine's convention, engines/dem/Simulation.cpp buildGhosts). The y image is chosen first and
// x wrapped after it, as the engine does, so a pair across the sheared boundary gets the branch
// vector the engine stored for it.
#include <array>
#include <cmath>

#include "core/Types.hpp"
#include "core/data/Domain.hpp"

namespace grainbridge::extract::structure {

class PeriodicBox {
 public:
  // Throws grainbridge::Error for a periodic axis with hi <= lo, or a Lees-Edwards offset
  // without periodic x and y.
  explicit PeriodicBox(const core::data::Domain& domain);

  // Shortest image of d = r_i - r_j. Pure arithmetic on d, so the same two positions always
  // give bitwise the same result whatever the caller's cell layout (ties in the MST stay ties).
  // Inline, and rounding only a component longer than half the box: the MST candidate search
  // calls this tens of millions of times and most pairs do not cross a boundary.
  [[nodiscard]] Vec3 minimumImage(Vec3 d) const {
    if (periodic_[1] && std::abs(d[1]) > halfLength_[1]) {
      const double images = std::round(d[1] / length_[1]);
      d[1] -= images * length_[1];
      d[0] -= images * leesEdwardsOffset_;
    }
    if (periodic_[0] && std::abs(d[0]) > halfLength_[0]) d[0] -= std::round(d[0] / length_[0]) * length_[0];
    if (periodic_[2] && std::abs(d[2]) > halfLength_[2]) d[2] -= std::round(d[2] / length_[2]) * length_[2];
    return d;
  }

  [[nodiscard]] bool periodic(int axis) const { return periodic_[static_cast<std::size_t>(axis)]; }
  [[nodiscard]] double lo(int axis) const { return lo_[axis]; }
  [[nodiscard]] double length(int axis) const { return length_[axis]; }
  [[nodiscard]] bool leesEdwards() const { return leesEdwardsOffset_ != 0.0; }
  [[nodiscard]] double leesEdwardsOffset() const { return leesEdwardsOffset_; }

 private:
  std::array<bool, 3> periodic_{};
  Vec3 lo_ = Vec3::Zero(), length_ = Vec3::Zero(), halfLength_ = Vec3::Zero();
  double leesEdwardsOffset_ = 0.0;
};

}  // namespace grainbridge::extract::structure
