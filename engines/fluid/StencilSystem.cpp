#include "engines/fluid/StencilSystem.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "core/Error.hpp"
#include "engines/fluid/PetscKsp.hpp"

// LAPACK (Fortran interface): Cholesky factorisation and solve of a symmetric positive definite
// band matrix; LU with partial pivoting of a band matrix, and the solve.
extern "C" void dpbsv_(const char* uplo, const int* n, const int* kd, const int* nrhs, double* ab, const int* ldab,
                       double* b, const int* ldb, int* info);
extern "C" void dgbsv_(const int* n, const int* kl, const int* ku, const int* nrhs, double* ab, const int* ldab,
                       int* ipiv, double* b, const int* ldb, int* info);

namespace grainbridge::fluid {

namespace {

// The padded neighbour of c in slot `n`, or nothing when the axis is not active (z in 2D).
bool neighbourOf(const StaggeredGrid& grid, std::size_t c, int n, std::size_t& out) {
  const int axis = n / 2;
  if (!grid.active(axis)) return false;
  out = grid.neighbour(c, axis, n % 2 == 0 ? -1 : +1);
  return true;
}

}  // namespace

StencilSystem::StencilSystem(const StaggeredGrid& grid)
    : grid_(&grid), ap_(grid.paddedCount(), 0.0), b_(grid.paddedCount(), 0.0), active_(grid.paddedCount(), 0) {
  // The active axes' slots only: a 2D grid has no z neighbours, and a system is built for every
  // equation of every outer iteration.
  for (int nb = 0; nb < 2 * grid.dimensions(); ++nb) anb_[static_cast<std::size_t>(nb)].assign(grid.paddedCount(), 0.0);
  for (int k = 0; k < grid.cells(2); ++k)
    for (int j = 0; j < grid.cells(1); ++j)
      for (int i = 0; i < grid.cells(0); ++i) active_[grid.index(i, j, k)] = 1;
}

namespace {

// The column ordering and symbolic analysis of a sparse LU depend only on the sparsity pattern,
// which is fixed by the active mask (every active neighbour gets an entry, zero or not); a solver
// assembles the same few patterns (a momentum component per axis, the pressure and fraction
// corrections) thousands of times, so each pattern is analysed once per thread and reused. The
// factorisation, and so the result, is the same as a fresh solver's.
using Lu = Eigen::SparseLU<Eigen::SparseMatrix<double>>;

Lu& analysedFor(const std::vector<char>& active, const Eigen::SparseMatrix<double>& A) {
  thread_local std::map<std::vector<char>, std::unique_ptr<Lu>> cache;
  auto it = cache.find(active);
  if (it == cache.end()) {
    if (cache.size() > 64) cache.clear();  // many grids in one process (tests): bound the memory
    auto lu = std::make_unique<Lu>();
    lu->analyzePattern(A);
    it = cache.emplace(active, std::move(lu)).first;
  }
  return *it->second;
}

// " at cell (i, j, k)" of the system's unknown (empty when there is none such).
std::string atCell(const StaggeredGrid& grid, const std::vector<long>& rowOfCell, long unknown) {
  for (std::size_t c = 0; c < rowOfCell.size(); ++c) {
    if (rowOfCell[c] != unknown) continue;
    const auto ijk = grid.coordinates(c);
    return " at cell (" + std::to_string(ijk[0]) + ", " + std::to_string(ijk[1]) + ", " + std::to_string(ijk[2]) + ")";
  }
  return {};
}

// Where a sparse LU met its zero pivot: Eigen reports the pivot's column in its fill-reducing
// order, one based, at the end of its message; the inverse column permutation gives the unknown.
std::string pivotCellOf(const StaggeredGrid& grid, const std::vector<long>& rowOfCell, const Lu& lu) {
  const std::string message = lu.lastErrorMessage();
  const std::size_t digits = message.find_last_not_of("0123456789");
  if (digits == std::string::npos || digits + 1 >= message.size()) return {};
  const long column = std::stol(message.substr(digits + 1)) - 1;
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> original = lu.colsPermutation().inverse();
  if (column < 0 || column >= original.indices().size()) return {};
  return atCell(grid, rowOfCell, original.indices()(column));
}

}  // namespace

namespace {

// Above this half-bandwidth the sparse LU is cheaper than the band LU (whose work grows as
// unknowns x bandwidth^2): a 2D grid numbered along its short side has the short side's cell
// count as its bandwidth; a 3D grid has a layer's.
constexpr long kBandLimit = 96;

// Solves A x = rhs by LAPACK's band LU (dgbsv). `entries` hold A; `bandwidth` bounds |row - col|.
// Returns dgbsv's info: 0 when solved, i > 0 when U(i, i) is zero (one based).
int solveBanded(long unknowns, long bandwidth, const std::vector<Eigen::Triplet<double>>& entries,
                Eigen::VectorXd& rhs) {
  const int n = static_cast<int>(unknowns), kl = static_cast<int>(bandwidth), ku = kl, nrhs = 1;
  const int ldab = 2 * kl + ku + 1;
  thread_local std::vector<double> band;
  thread_local std::vector<int> pivots;
  band.assign(static_cast<std::size_t>(ldab) * static_cast<std::size_t>(n), 0.0);
  pivots.resize(static_cast<std::size_t>(n));
  for (const auto& t : entries) {
    // A(i, j) at AB(kl + ku + i - j, j), column-major, zero-based.
    band[static_cast<std::size_t>(kl + ku + t.row() - t.col()) +
         static_cast<std::size_t>(t.col()) * static_cast<std::size_t>(ldab)] += t.value();
  }
  int info = 0;
  dgbsv_(&n, &kl, &ku, &nrhs, band.data(), &ldab, pivots.data(), rhs.data(), &n, &info);
  return info;
}

// Solves A x = rhs by LAPACK's band Cholesky (dpbsv) when A is symmetric; false, with rhs
// unchanged, when it is not, or not positive definite.
bool solveBandedCholesky(long unknowns, long bandwidth, const std::vector<Eigen::Triplet<double>>& entries,
                         Eigen::VectorXd& rhs) {
  const int n = static_cast<int>(unknowns), kd = static_cast<int>(bandwidth), nrhs = 1, ldab = kd + 1;
  thread_local std::vector<double> upper;
  upper.assign(static_cast<std::size_t>(ldab) * static_cast<std::size_t>(n), 0.0);
  // A(i, j), i <= j, at AB(kd + i - j, j) (LAPACK's upper storage). The entries come row by row,
  // one per neighbour, so A(j, i) below the diagonal meets its mirror A(i, j), stored when row i
  // came: the symmetry check as the band fills.
  for (const auto& t : entries) {
    const long i = std::min(t.row(), t.col()), j = std::max(t.row(), t.col());
    double& stored =
        upper[static_cast<std::size_t>(kd + i - j) + static_cast<std::size_t>(j) * static_cast<std::size_t>(ldab)];
    if (t.row() <= t.col()) {
      stored += t.value();
    } else if (stored != t.value()) {
      return false;
    }
  }
  Eigen::VectorXd x = rhs;
  int info = 0;
  dpbsv_("U", &n, &kd, &nrhs, upper.data(), &ldab, x.data(), &n, &info);
  if (info != 0) return false;
  rhs = std::move(x);
  return true;
}

}  // namespace

StencilSystem::Assembled StencilSystem::assemble(const std::vector<double>& phi) const {
  const std::size_t n = ap_.size();
  Assembled out;
  out.row.assign(n, -1);
  for (std::size_t c = 0; c < n; ++c) {
    if (active_[c] != 0) out.row[c] = out.unknowns++;
  }
  out.entries.reserve(static_cast<std::size_t>(out.unknowns) * 7);
  out.rhs.resize(out.unknowns);
  for (std::size_t c = 0; c < n; ++c) {
    if (active_[c] == 0) continue;
    if (ap_[c] == 0.0) throw Error("fluid: a_P is zero at padded cell " + std::to_string(c) + ": no equation there");
    const long r = out.row[c];
    out.entries.emplace_back(r, r, ap_[c]);
    double known = b_[c];
    for (int nb = 0; nb < 6; ++nb) {
      std::size_t m = 0;
      if (!neighbourOf(*grid_, c, nb, m)) continue;
      const double a = anb_[static_cast<std::size_t>(nb)][c];
      if (active_[m] != 0) {
        out.entries.emplace_back(r, out.row[m], -a);  // kept when zero: the pattern is the mask's
        out.bandwidth = std::max(out.bandwidth, std::abs(r - out.row[m]));
      } else {
        known += a * phi[m];  // a boundary value: known
      }
    }
    out.rhs[r] = known;
  }
  return out;
}

void StencilSystem::solveDirect(Assembled& system, std::vector<double>& phi, bool symmetric) const {
  Eigen::VectorXd x;
  if (symmetric && system.bandwidth <= kBandLimit &&
      solveBandedCholesky(system.unknowns, system.bandwidth, system.entries, system.rhs)) {
    x = std::move(system.rhs);
  } else if (system.bandwidth <= kBandLimit) {
    if (const int info = solveBanded(system.unknowns, system.bandwidth, system.entries, system.rhs); info != 0) {
      // A positive info is the one-based index of U's zero diagonal: that unknown's column.
      throw SingularSystem("fluid: the discretised system is singular (LAPACK dgbsv info " + std::to_string(info) +
                           ")" + atCell(*grid_, system.row, info - 1L));
    }
    x = std::move(system.rhs);
  } else {
    Eigen::SparseMatrix<double> A(system.unknowns, system.unknowns);
    A.setFromTriplets(system.entries.begin(), system.entries.end());
    A.makeCompressed();
    Lu& lu = analysedFor(active_, A);
    lu.factorize(A);
    if (lu.info() != Eigen::Success) {
      throw SingularSystem("fluid: the discretised system is singular (" + lu.lastErrorMessage() + ")" +
                           pivotCellOf(*grid_, system.row, lu));
    }
    x = lu.solve(system.rhs);
  }
  for (std::size_t c = 0; c < ap_.size(); ++c) {
    if (active_[c] != 0) phi[c] = x[system.row[c]];
  }
}

void StencilSystem::solve(std::vector<double>& phi) const { solve(phi, LinearSolve{}); }

bool StencilSystem::sweep(std::vector<double>& phi, const LinearSolve& how) const {
  const StaggeredGrid& grid = *grid_;
  std::array<std::ptrdiff_t, 6> offset{};
  std::array<bool, 6> used{};
  for (int nb = 0; nb < 6; ++nb) {
    const int axis = nb / 2;
    used[static_cast<std::size_t>(nb)] = grid.active(axis);
    if (used[static_cast<std::size_t>(nb)]) {
      const std::size_t c = grid.index(0, 0, 0);
      offset[static_cast<std::size_t>(nb)] =
          static_cast<std::ptrdiff_t>(grid.neighbour(c, axis, nb % 2 == 0 ? -1 : +1)) - static_cast<std::ptrdiff_t>(c);
    }
  }
  // The scale: the right-hand side with the boundary values moved over, as the LU sees it.
  double rhs2 = 0.0;
  for (std::size_t c = 0; c < ap_.size(); ++c) {
    if (active_[c] == 0) continue;
    if (ap_[c] == 0.0) throw Error("fluid: a_P is zero at padded cell " + std::to_string(c) + ": no equation there");
    double known = b_[c];
    for (int nb = 0; nb < 6; ++nb) {
      if (!used[static_cast<std::size_t>(nb)]) continue;
      const std::size_t m = c + static_cast<std::size_t>(offset[static_cast<std::size_t>(nb)]);
      if (active_[m] == 0) known += anb_[static_cast<std::size_t>(nb)][c] * phi[m];
    }
    rhs2 += known * known;
  }
  const double target2 = how.tolerance * how.tolerance * rhs2;
  // The sweeps visit only the active entries and the active axes' neighbours, in slot order (so
  // each sum adds up as it always has).
  std::vector<std::size_t> cells;
  for (std::size_t c = 0; c < ap_.size(); ++c) {
    if (active_[c] != 0) cells.push_back(c);
  }
  std::array<const double*, 6> coefficient{};
  std::array<std::ptrdiff_t, 6> step{};
  std::size_t slots = 0;
  for (int nb = 0; nb < 6; ++nb) {
    if (!used[static_cast<std::size_t>(nb)]) continue;
    coefficient[slots] = anb_[static_cast<std::size_t>(nb)].data();
    step[slots++] = offset[static_cast<std::size_t>(nb)];
  }
  double* x = phi.data();
  for (int iteration = 0; iteration < how.maxIterations; ++iteration) {
    double r2 = 0.0;
    for (const std::size_t c : cells) {
      double sum = b_[c];
      for (std::size_t k = 0; k < slots; ++k) sum += coefficient[k][c] * x[static_cast<std::ptrdiff_t>(c) + step[k]];
      const double r = sum - ap_[c] * x[c];
      r2 += r * r;
      x[c] += r / ap_[c];
    }
    if (!std::isfinite(r2)) return false;
    if (r2 <= target2) return true;
  }
  return false;
}

void StencilSystem::solve(std::vector<double>& phi, const LinearSolve& how) const {
  if (how.method == LinearSolve::Method::GaussSeidel) {
    const std::vector<double> start = phi;
    if (sweep(phi, how)) return;
    phi = start;  // not converged: the exact solve from where it began
  }
  if (how.method == LinearSolve::Method::Iterative && solveIterative(phi, how)) return;
  if (how.method == LinearSolve::Method::Petsc && solvePetsc(phi, how)) return;
  // Not converged (a system far from diagonal dominance): the exact solve.
  Assembled system = assemble(phi);
  if (system.unknowns == 0) return;  // no unknown (a velocity component across a single cell): nothing to solve
  solveDirect(system, phi, how.method == LinearSolve::Method::Cholesky);
}

struct StencilSystem::Rows {
  std::vector<int> rowOf, outer, inner;
  std::vector<double> values;
  Eigen::VectorXd rhs, guess;
};

int StencilSystem::compressedRows(const std::vector<double>& phi, Rows& rows) const {
  // The row-major matrix straight from the stencil, into buffers each thread keeps: a 3D grid
  // solves thousands of these per simulated second, and building them through triplets (a
  // temporary column-major copy, fresh allocations) cost as much as the solves. Each row holds
  // its entries by column, as setFromTriplets would leave them (the bottom, south and west
  // neighbours, the cell, then east, north, top: the padded order, which the rows keep), and the
  // right-hand side adds the known boundary values in slot order, as assemble() does.
  const std::size_t n = ap_.size();
  rows.rowOf.assign(n, -1);
  int unknowns = 0;
  for (std::size_t c = 0; c < n; ++c) {
    if (active_[c] != 0) rows.rowOf[c] = unknowns++;
  }
  rows.outer.resize(static_cast<std::size_t>(unknowns) + 1);
  rows.inner.clear();
  rows.values.clear();
  rows.rhs.resize(unknowns);
  rows.guess.resize(unknowns);
  constexpr std::array<int, 7> byColumn{Bottom, South, West, -1, East, North, Top};  // -1: the cell
  for (std::size_t c = 0; c < n; ++c) {
    if (active_[c] == 0) continue;
    if (ap_[c] == 0.0) throw Error("fluid: a_P is zero at padded cell " + std::to_string(c) + ": no equation there");
    const int r = rows.rowOf[c];
    rows.outer[static_cast<std::size_t>(r)] = static_cast<int>(rows.inner.size());
    double known = b_[c];
    for (int nb = 0; nb < 6; ++nb) {
      std::size_t m = 0;
      if (neighbourOf(*grid_, c, nb, m) && active_[m] == 0) known += anb_[static_cast<std::size_t>(nb)][c] * phi[m];
    }
    for (const int nb : byColumn) {
      if (nb < 0) {
        rows.inner.push_back(r);
        rows.values.push_back(ap_[c]);
        continue;
      }
      std::size_t m = 0;
      if (!neighbourOf(*grid_, c, nb, m) || active_[m] == 0) continue;
      rows.inner.push_back(rows.rowOf[m]);
      rows.values.push_back(-anb_[static_cast<std::size_t>(nb)][c]);  // kept when zero, as assemble() does
    }
    rows.rhs[r] = known;
    rows.guess[r] = phi[c];
  }
  rows.outer[static_cast<std::size_t>(unknowns)] = static_cast<int>(rows.inner.size());
  return unknowns;
}

bool StencilSystem::solveIterative(std::vector<double>& phi, const LinearSolve& how) const {
  thread_local Rows rows;
  const int unknowns = compressedRows(phi, rows);
  if (unknowns == 0) return true;  // nothing to solve
  const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>> A(
      unknowns, unknowns, static_cast<Eigen::Index>(rows.inner.size()), rows.outer.data(), rows.inner.data(),
      rows.values.data());
  Eigen::BiCGSTAB<Eigen::SparseMatrix<double, Eigen::RowMajor>, Eigen::DiagonalPreconditioner<double>> solver;
  solver.setTolerance(how.tolerance);
  solver.setMaxIterations(how.maxIterations);
  solver.compute(A);
  const Eigen::VectorXd x = solver.solveWithGuess(rows.rhs, rows.guess);
  if (solver.info() != Eigen::Success || !x.allFinite()) return false;
  for (std::size_t c = 0; c < ap_.size(); ++c) {
    if (active_[c] != 0) phi[c] = x[rows.rowOf[c]];
  }
  return true;
}

bool StencilSystem::solvePetsc(std::vector<double>& phi, const LinearSolve& how) const {
  thread_local Rows rows;
  const int unknowns = compressedRows(phi, rows);
  if (unknowns == 0) return true;  // nothing to solve
  const CompressedRows A{unknowns, rows.outer.data(), rows.inner.data(), rows.values.data()};
  Eigen::VectorXd x = rows.guess;
  if (!petscSolve(A, rows.rhs.data(), x.data(), how.tolerance, how.petscOptions) || !x.allFinite()) return false;
  for (std::size_t c = 0; c < ap_.size(); ++c) {
    if (active_[c] != 0) phi[c] = x[rows.rowOf[c]];
  }
  return true;
}

double StencilSystem::residual(const std::vector<double>& phi) const {
  double worst = 0.0;
  for (std::size_t c = 0; c < ap_.size(); ++c) {
    if (active_[c] == 0) continue;
    double r = ap_[c] * phi[c] - b_[c];
    for (int nb = 0; nb < 6; ++nb) {
      std::size_t m = 0;
      if (neighbourOf(*grid_, c, nb, m)) r -= anb_[static_cast<std::size_t>(nb)][c] * phi[m];
    }
    worst = std::max(worst, std::abs(r));
  }
  return worst;
}

double StencilSystem::neighbourSum(std::size_t c, const std::vector<double>& phi) const {
  double sum = b_[c];
  for (int nb = 0; nb < 6; ++nb) {
    std::size_t m = 0;
    if (neighbourOf(*grid_, c, nb, m)) sum += anb_[static_cast<std::size_t>(nb)][c] * phi[m];
  }
  return sum;
}

void StencilSystem::relax(double alpha, const std::vector<double>& phi) {
  for (std::size_t c = 0; c < ap_.size(); ++c) {
    if (active_[c] == 0) continue;
    ap_[c] /= alpha;
    b_[c] += (1.0 - alpha) * ap_[c] * phi[c];
  }
}

StencilSystem::Normalised StencilSystem::normalisedResidual(const std::vector<double>& phi, double scale) const {
  Normalised out;
  double sum = 0.0, diagonal = 0.0, worst = -1.0;
  for (std::size_t c = 0; c < ap_.size(); ++c) {
    if (active_[c] == 0) continue;
    const double r = std::abs(ap_[c] * phi[c] - neighbourSum(c, phi));
    sum += r;
    diagonal += std::abs(ap_[c]);
    if (r > worst) {
      worst = r;
      out.worst = c;
    }
  }
  out.value = diagonal > 0.0 && scale > 0.0 ? sum / diagonal / scale : 0.0;
  return out;
}

}  // namespace grainbridge::fluid
