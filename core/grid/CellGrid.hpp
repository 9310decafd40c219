#pragma once
// A uniform grid of cells over an axis-aligned box: the grid every particle-to-grid kernel
// deposits on (the fluid cells of TF-DEM, Eqs. 7.35-7.36, and the bins of coarse graining,
// Eq. 2.3). Cells are stored in C order [k][j][i] (i fastest), the order of core's FieldFrame,
// so a deposited field is written out without reordering.
//
// Periodic axes fold every periodic image of a particle or contact back into the box. Under
// Lees-Edwards shear (x flow, y gradient) the image above the box in y is displaced by the
// offset in x, exactly as the DEM engine builds its ghosts, so a kernel reaching across the
// shearing boundary lands in the cells its image really covers.
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

#include "core/Types.hpp"
#include "core/data/Domain.hpp"
#include "core/data/FieldFrame.hpp"
#include "core/grid/FastFloor.hpp"

namespace grainbridge::core::grid {

struct CellIndex {
  int i = 0, j = 0, k = 0;
  bool operator==(const CellIndex&) const = default;
};

class CellGrid {
 public:
  // Throws grainbridge::Error when an axis has hi <= lo or fewer than one cell.
  CellGrid(const Vec3& lo, const Vec3& hi, const std::array<int, 3>& counts,
           const std::array<bool, 3>& periodic = {false, false, false});
  // The box and periodicity of a frame's domain (with its Lees-Edwards offset), divided into counts.
  static CellGrid overDomain(const data::Domain& domain, const std::array<int, 3>& counts);

  [[nodiscard]] const Vec3& lo() const { return lo_; }
  [[nodiscard]] const Vec3& hi() const { return hi_; }
  [[nodiscard]] const std::array<int, 3>& counts() const { return counts_; }
  [[nodiscard]] const std::array<bool, 3>& periodic() const { return periodic_; }
  [[nodiscard]] Vec3 length() const { return hi_ - lo_; }
  [[nodiscard]] const Vec3& spacing() const { return spacing_; }
  [[nodiscard]] double cellVolume() const { return spacing_.prod(); }
  [[nodiscard]] std::size_t cellCount() const;

  // Lees-Edwards: the image above the box in y is displaced by +offset in x. Needs x and y
  // periodic; throws grainbridge::Error otherwise.
  [[nodiscard]] CellGrid withLeesEdwardsOffset(double offset) const;
  [[nodiscard]] double leesEdwardsOffset() const { return leesEdwardsOffset_; }

  [[nodiscard]] std::size_t flatIndex(const CellIndex& c) const {
    return (static_cast<std::size_t>(c.k) * static_cast<std::size_t>(counts_[1]) + static_cast<std::size_t>(c.j)) *
               static_cast<std::size_t>(counts_[0]) +
           static_cast<std::size_t>(c.i);
  }
  [[nodiscard]] CellIndex cellIndex(std::size_t flat) const;
  [[nodiscard]] bool contains(const CellIndex& c) const {
    return c.i >= 0 && c.i < counts_[0] && c.j >= 0 && c.j < counts_[1] && c.k >= 0 && c.k < counts_[2];
  }

  // The cell holding a point; periodic axes wrap (with the Lees-Edwards displacement across y),
  // a point outside the box on a non-periodic axis has no cell. Cells are half-open [lo, hi),
  // except that the upper face of a non-periodic box belongs to its last cell.
  [[nodiscard]] std::optional<CellIndex> cellOf(const Vec3& point) const;
  [[nodiscard]] Vec3 cellLo(const CellIndex& c) const;
  [[nodiscard]] Vec3 cellCentre(const CellIndex& c) const;
  // Index along one axis of the (possibly virtual, outside the box) cell holding coordinate x.
  [[nodiscard]] int axisCell(int axis, double x) const {
    // floor((x - lo) / spacing), by a multiplication where that gives the same floor: the
    // product carries two roundings more than the quotient, so it can only fall on the other
    // side of an integer when within a few ulps of it (a point on a face); those divide. Cell
    // lookups run several times per particle and contact, and a division's latency dominated.
    const double r = x - lo_[axis];
    const double q = r * inverseSpacing_[axis];
    const int i = floorToInt(q);
    const double margin = 1e-12 * (std::abs(q) + 1.0);
    if (q - i > margin && (i + 1) - q > margin) return i;
    return floorToInt(r / spacing_[axis]);
  }

  [[nodiscard]] data::GridGeometry geometry() const;

  // Calls visit(shift) once for every periodic image of an object with bounding box
  // [boxMin, boxMax] that reaches into the box: object + shift is that part of the object seen
  // in the frame of the box. Non-periodic axes have the single image shift 0 (the caller clips
  // or drops what lies outside). y goes first because its images are displaced in x.
  template <class Visit>
  void forEachImage(const Vec3& boxMin, const Vec3& boxMax, Visit&& visit) const {
    // Nearly every object lies inside the box on its periodic axes: its only image is itself.
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
      if (!periodic_[static_cast<std::size_t>(a)]) continue;
      inside = inside && imageOf(a, boxMin[a]) == 0.0 && imageOf(a, boxMax[a]) == 0.0;
    }
    if (inside) {
      visit(Vec3(Vec3::Zero()));
      return;
    }
    const Vec3 len = length();
    const auto range = [&](int axis, double a, double b) {
      if (!periodic_[static_cast<std::size_t>(axis)]) return std::array<int, 2>{0, 0};
      return std::array<int, 2>{static_cast<int>(imageOf(axis, a)), static_cast<int>(imageOf(axis, b))};
    };
    const auto ys = range(1, boxMin[1], boxMax[1]);
    for (int my = ys[0]; my <= ys[1]; ++my) {
      Vec3 shiftY = Vec3::Zero();
      shiftY[1] = -my * len[1];
      shiftY[0] = -my * leesEdwardsOffset_;
      const auto xs = range(0, boxMin[0] + shiftY[0], boxMax[0] + shiftY[0]);
      const auto zs = range(2, boxMin[2], boxMax[2]);
      for (int mx = xs[0]; mx <= xs[1]; ++mx) {
        for (int mz = zs[0]; mz <= zs[1]; ++mz) {
          visit(Vec3(shiftY[0] - mx * len[0], shiftY[1], -mz * len[2]));
        }
      }
    }
  }

  bool operator==(const CellGrid&) const = default;

 private:
  // floor((x - lo) / length) along a periodic axis: which image of the box holds x. Without the
  // division for x inside the box, where it is 0 exactly (0 <= x - lo < length gives a quotient
  // below 1): nearly every point and contact is.
  [[nodiscard]] double imageOf(int axis, double x) const {
    const double r = x - lo_[axis];
    const double len = hi_[axis] - lo_[axis];
    return r >= 0.0 && r < len ? 0.0 : floorExact(r / len);
  }

  Vec3 lo_, hi_, spacing_, inverseSpacing_;
  std::array<int, 3> counts_;
  std::array<bool, 3> periodic_;
  double leesEdwardsOffset_ = 0.0;
};

}  // namespace grainbridge::core::grid
