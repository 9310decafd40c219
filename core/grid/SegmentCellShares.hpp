#pragma once
// Shares a segment among the cells it passes through by the exact fraction of its length in
// each (clipping at the cell faces): how the bin kernel spreads a contact's r_ij F_ij of Eq. 2.3
// along the contact line from r_i to r_j. Periodic images fold back into the box (Lees-Edwards
// displaced across y); length outside the box on a non-periodic axis is dropped.
#include "core/Types.hpp"
#include "core/grid/CellGrid.hpp"
#include "core/grid/CellShare.hpp"

namespace grainbridge::core::grid {

// Replaces out with (cell, length in cell / segment length). A segment of zero length goes
// whole to the cell holding its point.
void segmentCellShares(const CellGrid& grid, const Vec3& start, const Vec3& end, CellShares& out);

}  // namespace grainbridge::core::grid
