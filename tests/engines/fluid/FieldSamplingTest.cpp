// The flow read at cells and points (FieldSampling.hpp): a linear field is reproduced exactly by
// the interpolation and the differences, and a point next to a no-slip wall sees the wall.
#include <gtest/gtest.h>

#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/FieldSampling.hpp"

using namespace grainbridge;
using namespace grainbridge::fluid;

namespace {

core::data::GridGeometry box(int nz) {
  core::data::GridGeometry g;
  g.origin = Vec3(0.1, -0.2, 0.0);
  g.cells = {4, 5, nz};
  g.spacing = Vec3(0.01, 0.02, 0.03);
  return g;
}

// u = (1 + 2x + 3y + 4z, -1 + x - y + 2z, 5 - z + x) on every face and ghost face.
Vec3 linear(const Vec3& p) {
  return {1.0 + 2.0 * p.x() + 3.0 * p.y() + 4.0 * p.z(), -1.0 + p.x() - p.y() + 2.0 * p.z(), 5.0 - p.z() + p.x()};
}

PhaseFields linearPhase(const StaggeredGrid& grid) {
  PhaseFields phase(grid);
  for (int a = 0; a < grid.dimensions(); ++a) {
    for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
      const auto [i, j, k] = grid.coordinates(f);
      phase.velocity[static_cast<std::size_t>(a)][f] = linear(grid.faceCentre(a, i, j, k))[a];
    }
  }
  return phase;
}

}  // namespace

TEST(FieldSampling, ALinearVelocityIsInterpolatedExactlyIn3D) {
  const StaggeredGrid grid(box(3));
  const PhaseFields phase = linearPhase(grid);
  for (const Vec3& p : {Vec3(0.1234, -0.1777, 0.0456), Vec3(0.1001, -0.1999, 0.0899), Vec3(0.1399, -0.1001, 0.0001)}) {
    const Vec3 v = velocityAt(phase, p);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(v[a], linear(p)[a], 1e-12) << a;
  }
  const std::size_t c = grid.index(2, 3, 1);
  const Vec3 centre = cellVelocity(phase, c);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(centre[a], linear(grid.cellCentre(2, 3, 1))[a], 1e-12) << a;
}

TEST(FieldSampling, In2DTheZComponentIsZeroAndZIsIgnored) {
  const StaggeredGrid grid(box(1));
  const PhaseFields phase = linearPhase(grid);
  const Vec3 v = velocityAt(phase, Vec3(0.125, -0.15, 0.02));
  const Vec3 atMidDepth = linear(Vec3(0.125, -0.15, 0.015));
  // The faces of a 2D grid sit at mid-depth: x and y see the field there, whatever the point's z.
  EXPECT_NEAR(v.x(), atMidDepth.x(), 1e-12);
  EXPECT_NEAR(v.y(), atMidDepth.y(), 1e-12);
  EXPECT_EQ(v.z(), 0.0);
}

TEST(FieldSampling, APointAtANoSlipWallSeesZeroTangentialVelocity) {
  const StaggeredGrid grid(box(1));
  Boundaries walls(grid, {}, 1);  // every side a no-slip wall
  FlowState state(grid, 1);
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    state.phases[0].fraction[c] = 1.0;
    if (grid.interior(c)) state.phases[0].velocity[1][c] = 0.7;  // upward along the x_low wall
  }
  walls.apply(state);
  const Vec3 atWall = velocityAt(state.phases[0], Vec3(0.1, -0.15, 0.0));
  EXPECT_NEAR(atWall.y(), 0.0, 1e-14);
  const Vec3 atCentre = velocityAt(state.phases[0], grid.cellCentre(0, 2, 0));
  EXPECT_NEAR(atCentre.y(), 0.7, 1e-14);
}

TEST(FieldSampling, ThePressureGradientOfALinearFieldIsExactInsideAndBesideWalls) {
  const StaggeredGrid grid(box(3));
  CellField p(grid, 0.0);
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    const auto [i, j, k] = grid.coordinates(c);
    const Vec3 x = grid.cellCentre(i, j, k);
    // Ghosts hold nonsense: a boundary's value is not the flow's.
    p[c] = grid.interior(c) ? 101325.0 + 50.0 * x.x() - 9000.0 * x.y() + 7.0 * x.z() : -1e9;
  }
  for (const auto& [i, j, k] : {std::array<int, 3>{0, 0, 0}, {2, 3, 1}, {3, 4, 2}}) {
    const Vec3 g = pressureGradient(p, grid.index(i, j, k));
    EXPECT_NEAR(g.x(), 50.0, 1e-6);
    EXPECT_NEAR(g.y(), -9000.0, 1e-6);
    EXPECT_NEAR(g.z(), 7.0, 1e-6);
  }
}
