// Eq. 3.64 assembled and solved: the seven-point diffusion stencil (Eqs. 3.58-3.59) is exact for
// quadratic fields, so a harmonic quadratic with its values in the ghost cells (the boundary)
// must come back at every cell centre to round-off, in 2D and 3D, on unequal spacings.
#include "engines/fluid/StencilSystem.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "core/Error.hpp"
#include "engines/fluid/PetscKsp.hpp"

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

// A singular system names the cell of its zero pivot, by the band LU (a narrow grid) and by the
// sparse LU (a large one): two cells (i0, 1) and (i0 + 1, 1) coupled to each other alone with
// rows x0 - x1 and x1 - x0, an exactly singular block that elimination meets exactly.
TEST(StencilSystem, ASingularSystemNamesTheCellOfItsZeroPivot) {
  for (const int nx : {6, 100}) {  // bandwidth 6 and 100, above the band LU's limit of 96
    const auto grid = makeGrid({nx, nx, 1}, Vec3(1, 1, 1));
    auto system = diffusion(grid, 1.0);
    const int i0 = nx / 2;
    const std::size_t c0 = grid.index(i0, 1, 0), c1 = grid.index(i0 + 1, 1, 0);
    for (const std::size_t c : {c0, c1}) {
      for (int nb = 0; nb < 4; ++nb) system.anb(c, nb) = 0.0;  // a 2D grid: west to north
      system.ap(c) = 1.0;
    }
    system.anb(c0, East) = 1.0;
    system.anb(c1, West) = 1.0;
    for (const auto& [c, nb] : {std::pair{grid.index(i0 - 1, 1, 0), East},
                                {grid.index(i0, 0, 0), North},
                                {grid.index(i0, 2, 0), South},
                                {grid.index(i0 + 2, 1, 0), West},
                                {grid.index(i0 + 1, 0, 0), North},
                                {grid.index(i0 + 1, 2, 0), South}})
      system.anb(c, nb) = 0.0;
    CellField phi(grid);
    try {
      system.solve(phi);
      ADD_FAILURE() << nx << ": a singular system was solved";
    } catch (const SingularSystem& e) {
      const std::string what = e.what();
      const bool named = what.find("at cell (" + std::to_string(i0) + ", 1, 0)") != std::string::npos ||
                         what.find("at cell (" + std::to_string(i0 + 1) + ", 1, 0)") != std::string::npos;
      EXPECT_TRUE(named) << nx << ": " << what;
      EXPECT_NE(what.find(nx > 96 ? "STRUCTURALLY SINGULAR" : "dgbsv"), std::string::npos) << what;
    }
  }
}

// The Poisson problem solved each way: the band Cholesky is exact for this symmetric positive
// definite system; the sweeps and BiCGSTAB reach their tolerance.
TEST(StencilSystem, EveryMethodSolvesThePoissonProblem) {
  const double s = 4.0;
  const auto grid = makeGrid({12, 9, 1}, Vec3(0.2, 0.3, 0.1));
  const auto exact = sampled(grid, [s](const Vec3& x) { return -s / 4.0 * (x.x() * x.x() + x.y() * x.y()) + x.x(); });
  std::vector<LinearSolve::Method> methods{LinearSolve::Method::Direct, LinearSolve::Method::Cholesky,
                                           LinearSolve::Method::Iterative, LinearSolve::Method::GaussSeidel};
  if (petscAvailable()) methods.push_back(LinearSolve::Method::Petsc);
  for (const auto method : methods) {
    CellField phi = exact;
    for (int j = 0; j < 9; ++j)
      for (int i = 0; i < 12; ++i) phi(i, j, 0) = 0.0;
    LinearSolve how;
    how.method = method;
    how.tolerance = 1e-12;
    how.maxIterations = 5000;
    how.petscOptions = "-ksp_type gmres -ksp_pc_side right -pc_type hypre -pc_hypre_type boomeramg";
    diffusion(grid, s).solve(phi.values(), how);
    const bool exactMethod = method == LinearSolve::Method::Direct || method == LinearSolve::Method::Cholesky;
    expectInteriorEqual(grid, phi, exact, exactMethod ? 1e-11 : 1e-9);
  }
}

// A diagonally dominant system (a momentum equation at a small step) converges in a few sweeps;
// where the sweeps cannot converge in the iterations allowed, the exact solve still answers.
TEST(StencilSystem, SweepsFallBackToTheExactSolve) {
  const auto grid = makeGrid({10, 10, 1}, Vec3(0.1, 0.1, 0.1));
  auto system = diffusion(grid, 1.0);
  CellField exact(grid, 0.0);
  system.solve(exact);
  LinearSolve sweeps;
  sweeps.method = LinearSolve::Method::GaussSeidel;
  sweeps.tolerance = 1e-12;
  sweeps.maxIterations = 2;  // far too few for the Poisson problem
  CellField phi(grid, 0.0);
  system.solve(phi.values(), sweeps);
  expectInteriorEqual(grid, phi, exact, 1e-12);
  // With a strong diagonal (a transient term), a few sweeps suffice to a coarse tolerance.
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i) system.ap(grid.index(i, j, 0)) *= 20.0;
  CellField strong(grid, 0.0);
  system.solve(strong);
  sweeps.tolerance = 1e-2;
  sweeps.maxIterations = 5;
  CellField swept(grid, 0.0);
  system.solve(swept.values(), sweeps);
  double worst = 0.0, scale = 0.0;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i) {
      worst = std::max(worst, std::abs(swept(i, j, 0) - strong(i, j, 0)));
      scale = std::max(scale, std::abs(strong(i, j, 0)));
    }
  EXPECT_GT(worst, 0.0);  // an inexact answer: the sweeps, not the fallback
  EXPECT_LT(worst, 1e-2 * scale);
}

// The Cholesky request on an asymmetric system (convection) is answered by the LU.
TEST(StencilSystem, CholeskyOfAnAsymmetricSystemIsTheLu) {
  const auto grid = makeGrid({6, 5, 1}, Vec3(0.1, 0.1, 0.1));
  auto system = diffusion(grid, 1.0);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 6; ++i) {
      const std::size_t c = grid.index(i, j, 0);
      system.anb(c, West) += 0.3;  // upwind convection from the west
      system.ap(c) += 0.3;
    }
  CellField lu(grid, 0.0), cholesky(grid, 0.0);
  system.solve(lu);
  LinearSolve how;
  how.method = LinearSolve::Method::Cholesky;
  system.solve(cholesky.values(), how);
  expectInteriorEqual(grid, cholesky, lu, 0.0);
  EXPECT_LT(system.residual(lu), 1e-12);
}

// A non-symmetric system (diffusion with upwind convection along x and y, as a momentum equation
// at a small step) solved by PETSc's KSP with the families' default options, to a
// relative tolerance of 1e-12 on the true residual (right preconditioning), and with block Jacobi
// (ILU(0) on one rank): the LU's solution to what that tolerance allows. Then the same pattern with other values: the
// kept solver must take the new matrix (its preconditioner set up again), not answer with the old one's.
TEST(StencilSystem, PetscSolvesANonSymmetricSystemAsTheLuDoesAndTakesNewValues) {
  if (!petscAvailable()) GTEST_SKIP() << petscBuildNote();
  const auto grid = makeGrid({14, 9, 1}, Vec3(0.1, 0.2, 0.1));
  for (const double flux : {3.0, -7.0}) {  // the second: the same pattern, other values
    auto system = diffusion(grid, 1.0);
    for (int j = 0; j < grid.cells(1); ++j)
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, 0);
        system.anb(c, flux > 0.0 ? West : East) += std::abs(flux);  // upwind
        system.anb(c, South) += 0.5 * std::abs(flux);
        system.ap(c) += 1.5 * std::abs(flux) + 2.0 + 0.1 * i;  // and a transient term
        system.b(c) += std::sin(0.7 * i) * std::cos(0.3 * j);
      }
    CellField boundary = sampled(grid, [](const Vec3& x) { return 1.0 + x.x() - 2.0 * x.y(); });
    CellField exact = boundary;
    system.solve(exact);
    double scale = 0.0;
    for (int j = 0; j < grid.cells(1); ++j)
      for (int i = 0; i < grid.cells(0); ++i) scale = std::max(scale, std::abs(exact(i, j, 0)));
    for (const char* options :
         {"-ksp_type bcgs -ksp_pc_side right -pc_type jacobi", "-ksp_type bcgs -ksp_pc_side right -pc_type bjacobi"}) {
      CellField phi = boundary;
      LinearSolve how;
      how.method = LinearSolve::Method::Petsc;
      how.tolerance = 1e-12;
      how.petscOptions = options;
      system.solve(phi.values(), how);
      expectInteriorEqual(grid, phi, exact, 1e-9 * scale);
    }
  }
}

// Options PETSc cannot use are found when the set-up is checked, with PETSc's reason: a type it
// does not know, and a misspelt option name (which PETSc itself would silently ignore).
TEST(StencilSystem, PetscOptionsAreCheckedBeforeAnySolve) {
  if (!petscAvailable()) GTEST_SKIP() << petscBuildNote();
  EXPECT_FALSE(petscOptionsProblem("-ksp_type gmres -ksp_pc_side right -pc_type hypre -pc_hypre_type boomeramg"));
  EXPECT_FALSE(petscOptionsProblem("-ksp_type bcgs -ksp_pc_side right -pc_type jacobi"));
  EXPECT_FALSE(petscOptionsProblem(""));
  const auto unknownType = petscOptionsProblem("-ksp_type nosuch");
  ASSERT_TRUE(unknownType);
  EXPECT_NE(unknownType->find("nosuch"), std::string::npos) << *unknownType;
  const auto misspelt = petscOptionsProblem("-ksp_typo gmres");
  ASSERT_TRUE(misspelt);
  EXPECT_NE(misspelt->find("-ksp_typo"), std::string::npos) << *misspelt;
}

}  // namespace
}  // namespace grainbridge::fluid
