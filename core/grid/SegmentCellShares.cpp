#include "core/grid/SegmentCellShares.hpp"

namespace grainbridge::core::grid {

void segmentCellShares(const CellGrid& grid, const Vec3& start, const Vec3& end, CellShares& out) {
  out.clear();
  forEachSegmentCell(grid, start, end, [&](std::size_t cell, double fraction) { out.push_back({cell, fraction}); });
}

}  // namespace grainbridge::core::grid
