// Eq. 3.64 assembled and solved: the seven-point diffusion stencil (Eqs. 3.58-3.59) is exact for
// quadratic fields, so a harmonic quadratic with its values in the ghost cells (the boundary)
// must come back at every cell centre to round-off, in 2D and 3D, on unequal spacings.
#include "engines/fluid/StencilSystem.hpp"

#include <gtest/gtest.h>

#include <functional>

#include "core/Error.hpp"

namespace grainbridge::fluid {
namespace {

StaggeredGrid makeGrid(std::array<int, 3> cells, Vec3 spacing) {
  core::data::GridGeometry g;
  g.origin = Vec3(-0.3, 0.2, 0.1);
  g.spacing = spacing;
  g.cells = cells;
  return StaggeredGrid(g);
}

// Diffusion with unit coefficient and a uniform source s per unit volume:
// a_nb = A_face / delta, a_P = sum a_nb, b = s V (Eqs. 3.58-3.59, 3.63).
StencilSystem diffusion(const StaggeredGrid& grid, double source) {
  StencilSystem system(grid);
  for (int k = 0; k < grid.cells(2); ++k)
    for (int j = 0; j < grid.cells(1); ++j)
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        double sum = 0.0;
        for (int axis = 0; axis < grid.dimensions(); ++axis) {
          const double a = grid.faceArea(axis) / grid.spacing(axis);
          system.anb(c, 2 * axis) = a;
          system.anb(c, 2 * axis + 1) = a;
          sum += 2.0 * a;
        }
        system.ap(c) = sum;
        system.b(c) = source * grid.cellVolume();
      }
  return system;
}

// phi at every padded cell centre from a function of position (ghosts: the boundary values).
CellField sampled(const StaggeredGrid& grid, const std::function<double(const Vec3&)>& f) {
  CellField phi(grid);
  const int gz = grid.ghosts(2);
  for (int k = -gz; k < grid.cells(2) + gz; ++k)
    for (int j = -1; j <= grid.cells(1); ++j)
      for (int i = -1; i <= grid.cells(0); ++i) phi(i, j, k) = f(grid.cellCentre(i, j, k));
  return phi;
}

void expectInteriorEqual(const StaggeredGrid& grid, const CellField& a, const CellField& b, double tolerance) {
  for (int k = 0; k < grid.cells(2); ++k)
    for (int j = 0; j < grid.cells(1); ++j)
      for (int i = 0; i < grid.cells(0); ++i)
        EXPECT_NEAR(a(i, j, k), b(i, j, k), tolerance) << i << ' ' << j << ' ' << k;
}

TEST(StencilSystem, HarmonicQuadraticIsExactIn2D) {
  const auto grid = makeGrid({8, 6, 1}, Vec3(0.5, 0.25, 0.1));
  const auto exact = sampled(grid, [](const Vec3& x) { return x.x() * x.x() - x.y() * x.y() + 3.0 * x.x() * x.y(); });
  CellField phi = exact;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 8; ++i) phi(i, j, 0) = 0.0;  // unknowns start wrong; ghosts hold the boundary
  const auto system = diffusion(grid, 0.0);
  EXPECT_GT(system.residual(phi), 1e-3);
  system.solve(phi);
  expectInteriorEqual(grid, phi, exact, 1e-12);
  EXPECT_LT(system.residual(phi), 1e-12);
}

TEST(StencilSystem, PoissonQuadraticIsExactIn3D) {
  // -laplacian(phi) = s with phi = -s/6 |x|^2 + harmonic terms.
  const double s = 4.0;
  const auto grid = makeGrid({4, 5, 3}, Vec3(0.2, 0.3, 0.25));
  const auto exact = sampled(grid, [s](const Vec3& x) { return -s / 6.0 * x.squaredNorm() + x.x() * x.z() - x.y(); });
  CellField phi = exact;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 4; ++i) phi(i, j, k) = 1.0;
  diffusion(grid, s).solve(phi);
  expectInteriorEqual(grid, phi, exact, 1e-12);
}

TEST(StencilSystem, ACellWithoutAnEquationIsRefused) {
  const auto grid = makeGrid({3, 3, 1}, Vec3(1, 1, 1));
  auto system = diffusion(grid, 0.0);
  system.ap(grid.index(1, 1, 0)) = 0.0;
  CellField phi(grid);
  EXPECT_THROW(system.solve(phi), Error);
}

}  // namespace
}  // namespace grainbridge::fluid
