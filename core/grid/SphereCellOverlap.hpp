#pragma once
// Shares a sphere among the cells it overlaps by exact volume (SphereBoxOverlap): the
// extension of Eqs. 7.35-7.36 the reference lists as future work. Periodic images fold back
// into the box (with the Lees-Edwards displacement across y); the part of a sphere outside the
// box on a non-periodic axis is dropped, so fractions sum to 1 only for a sphere inside the box.
#include "core/Types.hpp"
#include "core/grid/CellGrid.hpp"
#include "core/grid/CellShare.hpp"

namespace grainbridge::core::grid {

// Replaces out with (cell, overlap volume / sphere volume). A cell may appear more than once
// when a sphere reaches it through two periodic images; callers sum, so that is harmless.
void sphereCellShares(const CellGrid& grid, const Vec3& centre, double radius, CellShares& out);

}  // namespace grainbridge::core::grid
