#pragma once
// Minimum-image geometry of a frame's box for the spatial correlations of Eq. 6.12: a pair of
// contacts (or particles) on opposite faces of a periodic box is a short pair. Lees-Edwards
// follows the DEM engine's convention: the image above the box in y is displaced by +offset
// in x, so crossing y first shifts x, and x is wrapped afterwards.
#include <array>

#include "core/Types.hpp"
#include "core/data/Domain.hpp"

namespace grainbridge::extract::statistics {

class MinimumImage {
 public:
  // Throws grainbridge::Error if a periodic axis has hi <= lo, or if a Lees-Edwards offset or
  // shear rate is set on a box not periodic in both x and y.
  explicit MinimumImage(const core::data::Domain& domain);

  // a - b under the minimum image on the periodic axes (plain difference elsewhere).
  [[nodiscard]] Vec3 separation(const Vec3& a, const Vec3& b) const;
  // The image of p inside [lo, hi) on the periodic axes; other axes unchanged.
  [[nodiscard]] Vec3 wrap(const Vec3& p) const;
  // Largest distance for which the minimum image is unique: half the shortest periodic edge
  // (infinity when no axis is periodic).
  [[nodiscard]] double maxUniqueDistance() const;

  [[nodiscard]] bool periodic(int axis) const { return periodic_[static_cast<std::size_t>(axis)]; }
  [[nodiscard]] const Vec3& lo() const { return lo_; }
  [[nodiscard]] const Vec3& length() const { return length_; }
  // x displacement of the image one box above in y (0 without Lees-Edwards).
  [[nodiscard]] double shearOffset() const { return offset_; }

 private:
  Vec3 lo_, length_;
  std::array<bool, 3> periodic_{};
  double offset_ = 0.0;
};

}  // namespace grainbridge::extract::statistics
