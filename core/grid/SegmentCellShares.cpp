#include "core/grid/SegmentCellShares.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace grainbridge::core::grid {

void segmentCellShares(const CellGrid& grid, const Vec3& start, const Vec3& end, CellShares& out) {
  out.clear();
  const Vec3 d = end - start;
  if (d.squaredNorm() == 0.0) {
    if (const auto cell = grid.cellOf(start)) out.push_back({grid.flatIndex(*cell), 1.0});
    return;
  }
  const Vec3& lo = grid.lo();
  const Vec3& h = grid.spacing();
  std::vector<double> cuts;
  grid.forEachImage(start.cwiseMin(end), start.cwiseMax(end), [&](const Vec3& shift) {
    const Vec3 p = start + shift;
    // Parameters s in (0, 1) where the segment p + s d crosses a cell face.
    cuts.assign({0.0, 1.0});
    for (int a = 0; a < 3; ++a) {
      if (d[a] == 0.0) continue;
      const int c0 = grid.axisCell(a, p[a]);
      const int c1 = grid.axisCell(a, p[a] + d[a]);
      for (int f = std::min(c0, c1) + 1; f <= std::max(c0, c1); ++f) {
        const double s = (lo[a] + f * h[a] - p[a]) / d[a];
        if (s > 0.0 && s < 1.0) cuts.push_back(s);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t n = 0; n + 1 < cuts.size(); ++n) {
      const double ds = cuts[n + 1] - cuts[n];
      if (ds <= 0.0) continue;
      const Vec3 mid = p + 0.5 * (cuts[n] + cuts[n + 1]) * d;
      const CellIndex cell{grid.axisCell(0, mid[0]), grid.axisCell(1, mid[1]), grid.axisCell(2, mid[2])};
      if (grid.contains(cell)) out.push_back({grid.flatIndex(cell), ds});
    }
  });
}

}  // namespace grainbridge::core::grid
