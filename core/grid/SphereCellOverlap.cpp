#include "core/grid/SphereCellOverlap.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "core/grid/SphereBoxOverlap.hpp"

namespace grainbridge::core::grid {

void sphereCellShares(const CellGrid& grid, const Vec3& centre, double radius, CellShares& out) {
  out.clear();
  if (!(radius > 0.0)) throw Error("sphere-cell overlap: radius " + std::to_string(radius) + " must be positive");
  const double r3 = radius * radius * radius;
  const double volume = 4.0 / 3.0 * M_PI * r3;  // as in sphereBoxOverlapVolume: a whole sphere gives exactly 1
  const Vec3 reach = Vec3::Constant(radius);
  const Vec3& h = grid.spacing();
  grid.forEachImage(centre - reach, centre + reach, [&](const Vec3& shift) {
    const Vec3 c = centre + shift;
    std::array<int, 3> first{}, last{};
    for (int a = 0; a < 3; ++a) {
      const auto s = static_cast<std::size_t>(a);
      first[s] = std::max(0, grid.axisCell(a, c[a] - radius));
      last[s] = std::min(grid.counts()[s] - 1, grid.axisCell(a, c[a] + radius));
    }
    for (int k = first[2]; k <= last[2]; ++k) {
      for (int j = first[1]; j <= last[1]; ++j) {
        for (int i = first[0]; i <= last[0]; ++i) {
          const CellIndex cell{i, j, k};
          const Vec3 lo = grid.cellLo(cell);
          const double v = sphereBoxOverlapVolume(c, radius, lo, lo + h);
          if (v > 0.0) out.push_back({grid.flatIndex(cell), v / volume});
        }
      }
    }
  });
}

}  // namespace grainbridge::core::grid
