#pragma once
// Minimum-image geometry of a frame's box (core/data/Domain.hpp), shared by every extract step
// that pairs points across periodic faces: the spatial correlations of Eq. 6.12 and the MST
// candidate edges of Section 6.3.3. Periodic axes wrap; with Lees-Edwards the image above the
// box in y is shifted by +leesEdwardsOffset in x (the engine's convention, engines/dem/
// Simulation.cpp buildGhosts). The y image is chosen first and x wrapped after it, as the engine
// does, so a pair across the sheared boundary gets the branch vector the engine stored for it.
#include <array>
#include <cmath>
#include <cstdint>

#include "core/Types.hpp"
#include "core/data/Domain.hpp"

namespace grainbridge::extract::geometry {

class PeriodicBox {
 public:
  // Throws grainbridge::Error for a periodic axis whose length hi - lo is not positive and
  // finite, or a Lees-Edwards offset or shear rate on a box not periodic in both x and y.
  explicit PeriodicBox(const core::data::Domain& domain);

  // Shortest image of d = r_i - r_j under the convention above (plain difference on open axes).
  // Pure arithmetic on d, so the same two positions always give bitwise the same result whatever
  // the caller's cell layout (ties in the MST stay ties). Inline, and rounding only a component
  // longer than half the box: pair searches call this tens of millions of times and most pairs
  // do not cross a boundary.
  [[nodiscard]] Vec3 minimumImage(Vec3 d) const {
    if (periodic_[1] && std::abs(d[1]) > halfLength_[1]) {
      const double images = nearestInteger(d[1] / length_[1]);
      d[1] -= images * length_[1];
      d[0] -= images * leesEdwardsOffset_;
    }
    if (periodic_[0] && std::abs(d[0]) > halfLength_[0]) d[0] -= nearestInteger(d[0] / length_[0]) * length_[0];
    if (periodic_[2] && std::abs(d[2]) > halfLength_[2]) d[2] -= nearestInteger(d[2] / length_[2]) * length_[2];
    return d;
  }

  // The image of p inside [lo, hi) on the periodic axes; open axes unchanged.
  [[nodiscard]] Vec3 wrap(const Vec3& p) const;

  // Largest distance for which the minimum image is unique: half the shortest periodic edge
  // (infinity when no axis is periodic).
  [[nodiscard]] double maxUniqueDistance() const;

  [[nodiscard]] bool periodic(int axis) const { return periodic_[static_cast<std::size_t>(axis)]; }
  [[nodiscard]] const Vec3& lo() const { return lo_; }
  [[nodiscard]] const Vec3& length() const { return length_; }
  // x displacement of the image one box above in y (0 without Lees-Edwards).
  [[nodiscard]] double leesEdwardsOffset() const { return leesEdwardsOffset_; }

 private:
  // std::round (halves away from zero), bit for bit, without a library call: a call anywhere in
  // a pair-search loop makes the compiler keep that loop's values on the stack.
  static double nearestInteger(double x) {
    if (!(std::abs(x) < 0x1p52)) return x;                                 // already an integer (or NaN)
    const auto whole = static_cast<double>(static_cast<std::int64_t>(x));  // toward zero
    return std::abs(x - whole) >= 0.5 ? whole + std::copysign(1.0, x) : whole;
  }

  std::array<bool, 3> periodic_{};
  Vec3 lo_ = Vec3::Zero(), length_ = Vec3::Zero(), halfLength_ = Vec3::Zero();
  double leesEdwardsOffset_ = 0.0;
};

}  // namespace grainbridge::extract::geometry
