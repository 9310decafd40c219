// The staggered grid's indexing (Section 3.3.1, MFiX's ghost-layer convention): every padded cell
// has its own flat index, neighbours are one stride apart, boundary faces sit on the domain's
// walls, and a 2D grid has no z ghosts.
#include "engines/fluid/StaggeredGrid.hpp"

#include <gtest/gtest.h>

#include <set>

#include "core/Error.hpp"
#include "engines/fluid/Fields.hpp"

namespace grainbridge::fluid {
namespace {

core::data::GridGeometry geometry(std::array<int, 3> cells, Vec3 spacing, Vec3 origin = Vec3::Zero()) {
  core::data::GridGeometry g;
  g.origin = origin;
  g.spacing = spacing;
  g.cells = cells;
  return g;
}

TEST(StaggeredGrid, TwoDimensionalGridHasGhostsInXAndYOnly) {
  const StaggeredGrid grid(geometry({4, 3, 1}, Vec3(0.5, 0.25, 0.1), Vec3(1.0, 2.0, 0.0)));
  EXPECT_EQ(grid.dimensions(), 2);
  EXPECT_EQ(grid.ghosts(0), 1);
  EXPECT_EQ(grid.ghosts(2), 0);
  EXPECT_EQ(grid.paddedCount(), 6u * 5u * 1u);
  EXPECT_EQ(grid.index(-1, -1, 0), 0u);
  EXPECT_EQ(grid.index(4, 3, 0), grid.paddedCount() - 1);
  // Boundary faces lie on the domain's walls.
  EXPECT_DOUBLE_EQ(grid.faceCentre(0, -1, 0, 0).x(), 1.0);
  EXPECT_DOUBLE_EQ(grid.faceCentre(0, 3, 0, 0).x(), 1.0 + 4 * 0.5);
  EXPECT_DOUBLE_EQ(grid.faceCentre(1, 0, 2, 0).y(), 2.0 + 3 * 0.25);
  EXPECT_DOUBLE_EQ(grid.cellCentre(0, 0, 0).y(), 2.125);
  EXPECT_DOUBLE_EQ(grid.faceArea(0), 0.25 * 0.1);
  EXPECT_DOUBLE_EQ(grid.cellVolume(), 0.5 * 0.25 * 0.1);
}

TEST(StaggeredGrid, EveryPaddedCellHasItsOwnIndexAndNeighboursAreOneStrideApart) {
  const StaggeredGrid grid(geometry({3, 4, 5}, Vec3(1, 1, 1)));
  EXPECT_EQ(grid.dimensions(), 3);
  std::set<std::size_t> seen;
  for (int k = -1; k <= 5; ++k) {
    for (int j = -1; j <= 4; ++j) {
      for (int i = -1; i <= 3; ++i) {
        const std::size_t c = grid.index(i, j, k);
        ASSERT_LT(c, grid.paddedCount());
        EXPECT_TRUE(seen.insert(c).second) << i << ' ' << j << ' ' << k;
        if (i < 3) {
          EXPECT_EQ(grid.neighbour(c, 0, +1), grid.index(i + 1, j, k));
        }
        if (j > -1) {
          EXPECT_EQ(grid.neighbour(c, 1, -1), grid.index(i, j - 1, k));
        }
        if (k < 5) {
          EXPECT_EQ(grid.neighbour(c, 2, +1), grid.index(i, j, k + 1));
        }
      }
    }
  }
  EXPECT_EQ(seen.size(), grid.paddedCount());
  EXPECT_TRUE(grid.interior(0, 0, 0));
  EXPECT_FALSE(grid.interior(3, 0, 0));
  EXPECT_FALSE(grid.interior(0, -1, 0));
}

TEST(StaggeredGrid, RefusesEmptyAxesAndNonPositiveSpacing) {
  EXPECT_THROW(StaggeredGrid(geometry({0, 3, 1}, Vec3(1, 1, 1))), Error);
  EXPECT_THROW(StaggeredGrid(geometry({2, 3, 1}, Vec3(1, -1, 1))), Error);
}

TEST(Fields, GhostEntriesAreOrdinaryStorage) {
  const StaggeredGrid grid(geometry({2, 2, 1}, Vec3(1, 1, 1)));
  CellField p(grid, 101325.0);
  FaceField u(grid, 0);
  p(-1, 0, 0) = 5.0;  // a ghost cell: where a boundary condition writes
  EXPECT_EQ(p[grid.index(-1, 0, 0)], 5.0);
  EXPECT_EQ(p(1, 1, 0), 101325.0);
  u(-1, 0, 0) = 0.3;  // the low boundary face of row 0
  EXPECT_EQ(u.axis(), 0);
  EXPECT_EQ(u[grid.index(-1, 0, 0)], 0.3);
  EXPECT_EQ(u.values().size(), grid.paddedCount());
}

}  // namespace
}  // namespace grainbridge::fluid
