// Smooth-kernel shares: every particle and contact deposits exactly 1 in a periodic box (also
// across a Lees-Edwards boundary); the discrete normalisation is close to the continuous one
// when the kernel spans a cell or more; segment line integrals match a closed form (Gaussian)
// and brute-force quadrature (Lucy, clipped at the cutoff); a non-periodic face loses weight.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/Error.hpp"
#include "core/grid/KernelCellShares.hpp"

using namespace grainbridge;
using namespace grainbridge::core::grid;

namespace {
double total(const CellShares& shares) {
  double s = 0.0;
  for (const auto& x : shares) s += x.fraction;
  return s;
}

std::vector<SmoothingKernel> kernels(double w) { return {GaussianKernel(w), LucyKernel(w)}; }
}  // namespace

TEST(KernelCellShares, PointAndSegmentSharesSumToOneInAPeriodicBox) {
  const CellGrid plain(Vec3(0, 0, 0), Vec3(4, 3, 5), {8, 6, 10}, {true, true, true});
  const CellGrid sheared = plain.withLeesEdwardsOffset(0.77);
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  CellShares shares;
  for (const CellGrid* grid : {&plain, &sheared}) {
    for (const auto& kernel : kernels(0.6)) {
      for (int trial = 0; trial < 20; ++trial) {
        const Vec3 p(4 * u(rng), 3 * u(rng), 5 * u(rng));
        kernelPointShares(*grid, kernel, p, shares);
        EXPECT_NEAR(total(shares), 1.0, 1e-13);
        const Vec3 q = p + Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
        kernelSegmentShares(*grid, kernel, p, q, shares);
        EXPECT_NEAR(total(shares), 1.0, 1e-13);
      }
    }
  }
}

TEST(KernelCellShares, DiscreteNormalisationIsCloseToTheContinuousKernel) {
  // A cell's share is phi(x_c - p) V_cell divided by the lattice sum; with w of a cell or more
  // that sum is the continuous integral 1 to within a small fraction.
  const CellGrid grid(Vec3(0, 0, 0), Vec3(8, 8, 8), {16, 16, 16}, {true, true, true});
  const Vec3 p(3.13, 4.71, 2.02);
  CellShares shares;
  for (double w : {0.5, 1.0}) {  // one and two cells
    for (const auto& kernel : kernels(w)) {
      kernelPointShares(grid, kernel, p, shares);
      double worst = 0.0;
      for (const auto& s : shares) {
        Vec3 r = grid.cellCentre(grid.cellIndex(s.cell)) - p;
        for (int a = 0; a < 3; ++a) r[a] -= 8.0 * std::round(r[a] / 8.0);  // minimum image
        const double continuous = std::visit([&](const auto& k) { return k(r.norm()); }, kernel) * grid.cellVolume();
        worst = std::max(worst, std::abs(s.fraction / continuous - 1.0));
      }
      std::printf("w = %.2f %s: share / (phi V_cell) - 1 at most %.2e\n", w, kernel.index() == 0 ? "gaussian" : "lucy",
                  worst);
      EXPECT_LT(worst, w < 0.75 ? 3e-3 : 3e-4);
    }
  }
}

TEST(KernelCellShares, GaussianSegmentIntegralMatchesTheClosedForm) {
  // Inside the cutoff the truncated Gaussian is A exp(-r^2 / 2w^2) and
  //   int_0^1 exp(-|f - s d|^2 / 2w^2) ds = exp(-b^2 / 2w^2) sqrt(pi/2) w / |d| [erf(...) - erf(...)],
  // with b the distance from x to the line and s* the foot of the perpendicular.
  const double w = 0.8;
  const GaussianKernel gauss(w);
  const Vec3 x(0.1, 0.2, -0.1);
  for (const Vec3& d : {Vec3(1.0, 0.0, 0.0), Vec3(0.3, 0.8, -0.5), Vec3(1.2, 0.9, 0.0)}) {
    const Vec3 start(-0.4, 0.1, 0.2);
    const Vec3 f = x - start;
    const double dn = d.norm();
    const double sStar = f.dot(d) / (dn * dn);
    const double b2 = f.squaredNorm() - f.dot(d) * f.dot(d) / (dn * dn);
    const double exact =
        gauss(0.0) * std::exp(-0.5 * b2 / (w * w)) * std::sqrt(M_PI / 2) * w / dn *
        (std::erf((1 - sStar) * dn / (std::sqrt(2.0) * w)) - std::erf(-sStar * dn / (std::sqrt(2.0) * w)));
    const double quad = kernelSegmentIntegral(gauss, x, start, start + d);
    EXPECT_NEAR(quad / exact, 1.0, 1e-13) << d.transpose();
  }
}

TEST(KernelCellShares, SegmentIntegralMatchesBruteForce) {
  // Lucy: a segment crossing the support (its integrand is continuous at the cutoff, so the
  // midpoint rule converges as h^2); Gaussian: a wide kernel holding the whole segment.
  const Vec3 x(0.0, 0.0, 0.0);
  const Vec3 start(-1.5, 0.3, 0.1), end(1.2, 0.5, -0.2);
  for (const SmoothingKernel kernel : {SmoothingKernel(LucyKernel(0.4)), SmoothingKernel(GaussianKernel(1.5))}) {
    double brute = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      const double s = (i + 0.5) / n;
      brute += std::visit([&](const auto& k) { return k((x - start - s * (end - start)).norm()); }, kernel) / n;
    }
    const double exact = kernelSegmentIntegral(kernel, x, start, end);
    EXPECT_NEAR(exact / brute, 1.0, 1e-9) << kernel.index();
  }
  // Entirely outside the support: nothing.
  EXPECT_EQ(kernelSegmentIntegral(LucyKernel(0.1), x, start, start + Vec3(0, 0, 0.1)), 0.0);
}

TEST(KernelCellShares, ZeroLengthSegmentIsThePoint) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(2, 2, 2), {4, 4, 4}, {true, true, true});
  CellShares a, b;
  const Vec3 p(0.3, 1.9, 1.1);
  kernelPointShares(grid, LucyKernel(0.3), p, a);
  kernelSegmentShares(grid, LucyKernel(0.3), p, p, b);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t n = 0; n < a.size(); ++n) {
    EXPECT_EQ(a[n].cell, b[n].cell);
    EXPECT_NEAR(a[n].fraction, b[n].fraction, 1e-15);
  }
}

TEST(KernelCellShares, NonPeriodicFaceLosesTheWeightBeyondIt) {
  // Normalised over the infinite lattice: a particle deep inside deposits 1, one at the face
  // about half (the cells beyond the face are not in the grid).
  const CellGrid grid(Vec3(0, 0, 0), Vec3(6, 6, 6), {12, 12, 12});
  CellShares shares;
  kernelPointShares(grid, LucyKernel(0.5), Vec3(3.1, 2.9, 3.0), shares);
  EXPECT_NEAR(total(shares), 1.0, 1e-13);
  kernelPointShares(grid, LucyKernel(0.5), Vec3(0.0, 2.9, 3.0), shares);
  EXPECT_NEAR(total(shares), 0.5, 0.02);
}

TEST(KernelCellShares, KernelNarrowerThanTheCellsIsAnError) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(4, 4, 4), {4, 4, 4});
  EXPECT_NO_THROW(checkKernelResolvesGrid(grid, GaussianKernel(0.3)));  // cutoff 0.9 > 0.866
  try {
    checkKernelResolvesGrid(grid, LucyKernel(0.2));  // cutoff 0.69
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("kernel width 0.2"), std::string::npos) << e.what();
  }
}
