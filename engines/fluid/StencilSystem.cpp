#include "engines/fluid/StencilSystem.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "core/Error.hpp"

// LAPACK: LU with partial pivoting of a band matrix, and the solve (Fortran interface).
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
  for (auto& a : anb_) a.assign(grid.paddedCount(), 0.0);
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

}  // namespace

namespace {

// Above this half-bandwidth the sparse LU is cheaper than the band LU (whose work grows as
// unknowns x bandwidth^2): a 2D grid numbered along its short side has the short side's cell
// count as its bandwidth; a 3D grid has a layer's.
constexpr long kBandLimit = 96;

// Solves A x = rhs by LAPACK's band LU (dgbsv). `entries` hold A; `bandwidth` bounds |row - col|.
bool solveBanded(long unknowns, long bandwidth, const std::vector<Eigen::Triplet<double>>& entries,
                 Eigen::VectorXd& rhs, std::string& failure) {
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
  if (info != 0) failure = "LAPACK dgbsv info " + std::to_string(info);
  return info == 0;
}

}  // namespace

void StencilSystem::solve(std::vector<double>& phi) const {
  const std::size_t n = ap_.size();
  std::vector<long> row(n, -1);
  long unknowns = 0;
  for (std::size_t c = 0; c < n; ++c) {
    if (active_[c] != 0) row[c] = unknowns++;
  }
  if (unknowns == 0) return;  // no unknown (a velocity component across a single cell): nothing to solve
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(unknowns) * 7);
  Eigen::VectorXd rhs(unknowns);
  long bandwidth = 0;
  for (std::size_t c = 0; c < n; ++c) {
    if (active_[c] == 0) continue;
    if (ap_[c] == 0.0) throw Error("fluid: a_P is zero at padded cell " + std::to_string(c) + ": no equation there");
    entries.emplace_back(row[c], row[c], ap_[c]);
    double known = b_[c];
    for (int nb = 0; nb < 6; ++nb) {
      std::size_t m = 0;
      if (!neighbourOf(*grid_, c, nb, m)) continue;
      const double a = anb_[static_cast<std::size_t>(nb)][c];
      if (active_[m] != 0) {
        entries.emplace_back(row[c], row[m], -a);  // kept when zero: the pattern is the mask's
        bandwidth = std::max(bandwidth, std::abs(row[c] - row[m]));
      } else {
        known += a * phi[m];  // a boundary value: known
      }
    }
    rhs[row[c]] = known;
  }
  Eigen::VectorXd x;
  if (bandwidth <= kBandLimit) {
    std::string failure;
    if (!solveBanded(unknowns, bandwidth, entries, rhs, failure))
      throw SingularSystem("fluid: the discretised system is singular (" + failure + ")");
    x = std::move(rhs);
  } else {
    Eigen::SparseMatrix<double> A(unknowns, unknowns);
    A.setFromTriplets(entries.begin(), entries.end());
    A.makeCompressed();
    Lu& lu = analysedFor(active_, A);
    lu.factorize(A);
    if (lu.info() != Eigen::Success)
      throw SingularSystem("fluid: the discretised system is singular (" + lu.lastErrorMessage() + ")");
    x = lu.solve(rhs);
  }
  for (std::size_t c = 0; c < n; ++c) {
    if (active_[c] != 0) phi[c] = x[row[c]];
  }
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
