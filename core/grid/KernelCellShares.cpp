#include "core/grid/KernelCellShares.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::core::grid {

namespace {

template <class Kernel>
double segmentIntegral(const Kernel& kernel, const Vec3& x, const Vec3& start, const Vec3& end) {
  const Vec3 d = end - start;
  const Vec3 f = x - start;
  const double length = d.norm();
  const double c = kernel.cutoff();
  if (length == 0.0) return kernel(f.norm());
  // Foot of the perpendicular from x at s*, distance b; the support is |t| < sqrt(c^2 - b^2)
  // with t = (s - s*) |d| the length along the segment from the foot.
  const double sStar = f.dot(d) / (length * length);
  const double b = (f - sStar * d).norm();
  if (b >= c) return 0.0;
  const double half = std::sqrt((c - b) * (c + b));
  const double t0 = std::max(-sStar * length, -half);
  const double t1 = std::min((1.0 - sStar) * length, half);
  if (t1 <= t0) return 0.0;
  return kernel.lineIntegral(b, t0, t1) / length;
}

// Visits every lattice cell whose centre lies in [lower, upper] (a bounding box of the
// kernel's support) in each periodic image, calls value(centre in the object's frame), and
// keeps the cells inside the box; normalises by the sum over all visited cells.
template <class Value>
void normalisedLatticeShares(const CellGrid& grid, const Vec3& lower, const Vec3& upper, Value&& value, CellShares& out,
                             const char* what) {
  out.clear();
  double total = 0.0;
  const Vec3& lo = grid.lo();
  const Vec3& h = grid.spacing();
  grid.forEachImage(lower, upper, [&](const Vec3& shift) {
    std::array<int, 3> first{}, last{};
    for (int a = 0; a < 3; ++a) {
      const auto s = static_cast<std::size_t>(a);
      first[s] = static_cast<int>(std::ceil((lower[a] + shift[a] - lo[a]) / h[a] - 0.5));
      last[s] = static_cast<int>(std::floor((upper[a] + shift[a] - lo[a]) / h[a] - 0.5));
      // Other images cover the rest of a periodic axis; a non-periodic axis keeps its virtual
      // cells for the normalisation.
      if (grid.periodic()[s]) {
        first[s] = std::max(first[s], 0);
        last[s] = std::min(last[s], grid.counts()[s] - 1);
      }
    }
    for (int k = first[2]; k <= last[2]; ++k) {
      for (int j = first[1]; j <= last[1]; ++j) {
        for (int i = first[0]; i <= last[0]; ++i) {
          const CellIndex cell{i, j, k};
          const double v = value(grid.cellCentre(cell) - shift);
          if (v <= 0.0) continue;
          total += v;
          if (grid.contains(cell)) out.push_back({grid.flatIndex(cell), v});
        }
      }
    }
  });
  if (!(total > 0.0)) {
    throw Error(std::string("kernel deposition: the ") + what +
                " reaches no cell centre; the kernel cutoff must exceed half the cell diagonal");
  }
  for (auto& share : out) share.fraction /= total;
}

}  // namespace

double kernelSegmentIntegral(const SmoothingKernel& kernel, const Vec3& x, const Vec3& start, const Vec3& end) {
  return std::visit([&](const auto& k) { return segmentIntegral(k, x, start, end); }, kernel);
}

void checkKernelResolvesGrid(const CellGrid& grid, const SmoothingKernel& kernel) {
  const double cutoff = std::visit([](const auto& k) { return k.cutoff(); }, kernel);
  const double halfDiagonal = 0.5 * grid.spacing().norm();
  if (!(cutoff > halfDiagonal)) {
    const double width = std::visit([](const auto& k) { return k.width(); }, kernel);
    std::ostringstream msg;
    msg << "coarse graining: kernel width " << width << " (cutoff " << cutoff
        << ") is too narrow for cells of diagonal " << 2.0 * halfDiagonal
        << "; the cutoff must exceed half the cell diagonal, or use more, smaller cells";
    throw Error(msg.str());
  }
}

void kernelPointShares(const CellGrid& grid, const SmoothingKernel& kernel, const Vec3& point, CellShares& out) {
  std::visit(
      [&](const auto& k) {
        const Vec3 reach = Vec3::Constant(k.cutoff());
        normalisedLatticeShares(
            grid, point - reach, point + reach, [&](const Vec3& centre) { return k((centre - point).norm()); }, out,
            "particle");
      },
      kernel);
}

void kernelSegmentShares(const CellGrid& grid, const SmoothingKernel& kernel, const Vec3& start, const Vec3& end,
                         CellShares& out) {
  std::visit(
      [&](const auto& k) {
        const Vec3 reach = Vec3::Constant(k.cutoff());
        normalisedLatticeShares(
            grid, start.cwiseMin(end) - reach, start.cwiseMax(end) + reach,
            [&](const Vec3& centre) { return segmentIntegral(k, centre, start, end); }, out, "contact segment");
      },
      kernel);
}

}  // namespace grainbridge::core::grid
