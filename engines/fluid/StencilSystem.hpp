#pragma once
// The discretised form every transport equation of the framework takes on a staggered grid,
// Eq. 3.64:   a_P Phi_P = sum_nb a_nb Phi_nb + b
// with the six neighbours W, E, S, N, B, T (fewer in 2D). Coefficients live per padded cell; the
// unknowns are the cells marked active (the interior for a scalar; a face's interior for a
// velocity component), and a neighbour that is not active (a ghost cell holding a boundary
// value, Eqs. 3.66-3.67) is known: its term moves to the right-hand side. `solve` is direct:
// LAPACK's band LU (dgbsv) when the unknowns' numbering keeps the matrix within a narrow band
// (2D grids, x numbered first: the band is a row of cells; measured 20 times faster than the
// sparse LU on the 15 x 45 Goldschmidt bed), Eigen's sparse LU otherwise; both single-threaded,
// so equal inputs give bit-equal results (a resumed run repeats an uninterrupted one).
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "engines/fluid/Fields.hpp"
#include "engines/fluid/StaggeredGrid.hpp"

namespace grainbridge::fluid {

// A discretised system with no unique solution (a zero pivot): from a bad iterate of a transient
// step, which a smaller step usually avoids (SimpleStep retries it), or a set-up that leaves a
// cell without an equation.
class SingularSystem : public Error {
 public:
  using Error::Error;
};

// How a system is solved.
// - Direct: the band or sparse LU above, exact to round-off.
// - Cholesky: for a system the caller knows to be symmetric positive definite (an incompressible
//   phase's pressure correction with a fixed level), LAPACK's band Cholesky (dpbsv), about half
//   the band LU's work; the LU wherever the matrix turns out not to be (asymmetric, not banded or
//   not definite).
// - Iterative: Eigen's BiCGSTAB with a diagonal preconditioner, from the values `phi` holds, to a
//   residual |A x - b| <= tolerance |b|.
// - GaussSeidel: point Gauss-Seidel sweeps on the stencil itself (no matrix is assembled; MFiX's
//   leq_sor with omega 1), until the root-mean-square residual falls to tolerance times that of
//   the right-hand side.
// - Petsc: PETSc's KSP (engines/fluid/PetscKsp.hpp) with the options string `petscOptions`, to
//   KSP's relative tolerance `tolerance` (issue 58).
// The last three take the direct solve when they do not converge (within maxIterations). For strongly
// diagonally dominant systems (momentum at a small step, where rho eps dV / dt dwarfs the
// neighbour coefficients) they need a few iterations where the LU needs a band's worth of work per
// row. An inner solve need not be exact: an outer iteration's convergence test reads the residual
// before the solve.
struct LinearSolve {
  enum class Method { Direct, Cholesky, Iterative, GaussSeidel, Petsc };
  Method method = Method::Direct;
  double tolerance = 1e-8;
  int maxIterations = 100;
  std::string petscOptions;  // Petsc: a PETSc options string ("-ksp_type gmres -pc_type hypre")
};

// Neighbour slots: 2 * axis for the low side (W, S, B), 2 * axis + 1 for the high side (E, N, T).
enum Neighbour : int { West = 0, East = 1, South = 2, North = 3, Bottom = 4, Top = 5 };

class StencilSystem {
 public:
  // All coefficients zero; the interior cells active.
  explicit StencilSystem(const StaggeredGrid& grid);
  // The place of an equation that is not solved (a phase given, not solved): it holds no
  // coefficients, and nothing may read or solve it.
  [[nodiscard]] static StencilSystem unsolved(const StaggeredGrid& grid) { return StencilSystem(&grid); }

  [[nodiscard]] const StaggeredGrid& grid() const { return *grid_; }
  [[nodiscard]] double& ap(std::size_t c) { return ap_[c]; }
  [[nodiscard]] double& anb(std::size_t c, int neighbour) { return anb_[static_cast<std::size_t>(neighbour)][c]; }
  [[nodiscard]] double& b(std::size_t c) { return b_[c]; }
  [[nodiscard]] double ap(std::size_t c) const { return ap_[c]; }
  [[nodiscard]] double anb(std::size_t c, int neighbour) const { return anb_[static_cast<std::size_t>(neighbour)][c]; }
  [[nodiscard]] double b(std::size_t c) const { return b_[c]; }
  // sum_nb a_nb Phi_nb + b at cell c: what a_P Phi_P balances.
  [[nodiscard]] double neighbourSum(std::size_t c, const std::vector<double>& phi) const;
  // Patankar's implicit under-relaxation with factor alpha in (0, 1]: a_P / alpha, and
  // (1 - alpha) a_P / alpha Phi* added to b, so a converged solution is unchanged.
  void relax(double alpha, const std::vector<double>& phi);
  void setActive(std::size_t c, bool active) { active_[c] = active ? 1 : 0; }
  [[nodiscard]] bool active(std::size_t c) const { return active_[c] != 0; }

  // Solves for the active cells of `phi`; its other entries are the known boundary values.
  // Throws grainbridge::Error naming the cell for a zero a_P (no equation there), SingularSystem
  // when the factorisation meets a zero pivot.
  void solve(std::vector<double>& phi) const;
  void solve(CellField& phi) const { solve(phi.values()); }
  void solve(FaceField& phi) const { solve(phi.values()); }
  // The same by `how` (an iterative solve starts from phi's active values).
  void solve(std::vector<double>& phi, const LinearSolve& how) const;
  void solve(FaceField& phi, const LinearSolve& how) const { solve(phi.values(), how); }
  void solve(CellField& phi, const LinearSolve& how) const { solve(phi.values(), how); }
  // The largest |a_P Phi_P - sum a_nb Phi_nb - b| over the active cells: the residual the
  // solver's convergence test reads.
  [[nodiscard]] double residual(const std::vector<double>& phi) const;
  [[nodiscard]] double residual(const CellField& phi) const { return residual(phi.values()); }
  // The mean residual per unit a_P, sum |a_P Phi_P - sum a_nb Phi_nb - b| / sum |a_P|, in units
  // of Phi, over `scale` (a typical magnitude of Phi: for a velocity, the phase's largest speed),
  // and the cell with the largest term. Unlike a division by sum |a_P Phi_P| it stays meaningful
  // for a component that is zero everywhere (the cross-stream velocity of a column).
  struct Normalised {
    double value = 0.0;
    std::size_t worst = 0;
  };
  [[nodiscard]] Normalised normalisedResidual(const std::vector<double>& phi, double scale) const;

 private:
  // The active cells' equations as a matrix: each active cell's row, the entries (the pattern is
  // the active mask's: zero coefficients kept), the right-hand side with the known boundary
  // values moved over, and the largest |row - column|.
  struct Assembled {
    std::vector<long> row;
    long unknowns = 0;
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd rhs;
    long bandwidth = 0;
  };
  [[nodiscard]] Assembled assemble(const std::vector<double>& phi) const;
  void solveDirect(Assembled& system, std::vector<double>& phi, bool symmetric) const;
  // The active cells' equations as compressed rows, in buffers each thread keeps (StencilSystem.cpp).
  struct Rows;
  // Fills `rows` from the stencil and phi's boundary values; the number of unknowns.
  int compressedRows(const std::vector<double>& phi, Rows& rows) const;
  // Jacobi-preconditioned BiCGSTAB from phi; false (phi unchanged) when it did not converge.
  bool solveIterative(std::vector<double>& phi, const LinearSolve& how) const;
  // PETSc's KSP from phi; false (phi unchanged) when it did not converge.
  bool solvePetsc(std::vector<double>& phi, const LinearSolve& how) const;
  // Gauss-Seidel sweeps; false (phi then holds the last sweep) when they did not converge.
  bool sweep(std::vector<double>& phi, const LinearSolve& how) const;

  // unsolved(): no storage.
  explicit StencilSystem(const StaggeredGrid* grid) : grid_(grid) {}

  const StaggeredGrid* grid_;
  std::vector<double> ap_, b_;
  std::array<std::vector<double>, 6> anb_;  // the active axes' slots (2 * dimensions) hold values
  std::vector<char> active_;
};

}  // namespace grainbridge::fluid
