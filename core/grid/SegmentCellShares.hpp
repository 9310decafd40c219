#pragma once
// Shares a segment among the cells it passes through by the exact fraction of its length in
// each (clipping at the cell faces): how the bin kernel spreads a contact's r_ij F_ij of Eq. 2.3
// along the contact line from r_i to r_j. Periodic images fold back into the box (Lees-Edwards
// displaced across y); length outside the box on a non-periodic axis is dropped.
//
// The cells are found by a 3-D DDA walk (Amanatides & Woo): along each axis the faces the
// segment crosses come in order of the line parameter s, so merging the three axes' next
// crossings visits the cells in order without sorting or allocating. This runs once per contact
// per frame, so it must not allocate. Each piece's fraction is the difference of two face
// parameters s = (face - start) / d, computed exactly as a sort of all crossings would.
#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

#include "core/Types.hpp"
#include "core/grid/CellGrid.hpp"
#include "core/grid/CellShare.hpp"

namespace grainbridge::core::grid {

namespace detail {

// Walks the segment p + s d, s in [0, 1], through the (possibly virtual) cells of the lattice of
// grid and calls visit(flat index, length fraction) for each piece of positive length in a cell
// of the box, in order of s.
template <class Visit>
void walkSegment(const CellGrid& grid, const Vec3& p, const Vec3& d, Visit& visit) {
  constexpr double never = std::numeric_limits<double>::infinity();
  const Vec3& lo = grid.lo();
  const Vec3& h = grid.spacing();
  std::array<int, 3> cell{}, step{}, face{}, facesLeft{};
  std::array<double, 3> next{};  // parameter s of the next face crossed along each axis
  const auto faceParameter = [&](int a, int f) { return (lo[a] + f * h[a] - p[a]) / d[a]; };
  for (int a = 0; a < 3; ++a) {
    const auto s = static_cast<std::size_t>(a);
    cell[s] = grid.axisCell(a, p[a]);
    next[s] = never;
    if (d[a] == 0.0) continue;
    const int last = grid.axisCell(a, p[a] + d[a]);
    // Face f is the lower face of cell f: going up from cell c the next face is c + 1, going
    // down it is c.
    step[s] = d[a] > 0.0 ? 1 : -1;
    face[s] = d[a] > 0.0 ? cell[s] + 1 : cell[s];
    facesLeft[s] = std::abs(last - cell[s]);
    if (facesLeft[s] > 0) next[s] = faceParameter(a, face[s]);
  }
  const auto emit = [&](double ds) {
    const CellIndex c{cell[0], cell[1], cell[2]};
    if (ds > 0.0 && grid.contains(c)) visit(grid.flatIndex(c), ds);
  };
  double from = 0.0;
  for (;;) {
    const auto a = static_cast<std::size_t>(std::min_element(next.begin(), next.end()) - next.begin());
    const double s = next[a];
    if (!(s < 1.0)) break;  // no face crossed before the end (or none at all)
    // A face at s <= 0 (the start lies on it, or round-off puts it a hair behind) only moves
    // the walk into the cell beyond it.
    if (s > 0.0) {
      emit(s - from);
      from = s;
    }
    cell[a] += step[a];
    face[a] += step[a];
    next[a] = --facesLeft[a] > 0 ? faceParameter(static_cast<int>(a), face[a]) : never;
  }
  emit(1.0 - from);
}

}  // namespace detail

// Calls visit(flat cell index, length in cell / segment length) for every piece of the segment
// from start to end in a cell of the box, image by image. A segment of zero length goes whole to
// the cell holding its point.
template <class Visit>
void forEachSegmentCell(const CellGrid& grid, const Vec3& start, const Vec3& end, Visit&& visit) {
  const Vec3 d = end - start;
  if (d.squaredNorm() == 0.0) {
    if (const auto cell = grid.cellOf(start)) visit(grid.flatIndex(*cell), 1.0);
    return;
  }
  grid.forEachImage(start.cwiseMin(end), start.cwiseMax(end),
                    [&](const Vec3& shift) { detail::walkSegment(grid, start + shift, d, visit); });
}

// Replaces out with (cell, length in cell / segment length), as forEachSegmentCell visits them.
void segmentCellShares(const CellGrid& grid, const Vec3& start, const Vec3& end, CellShares& out);

}  // namespace grainbridge::core::grid
