#include "extract/structure/CandidatePairs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::structure {

namespace {

std::int64_t floorDiv(std::int64_t a, std::int64_t n) { return a >= 0 ? a / n : -((-a + n - 1) / n); }

// One axis of the cell grid. Periodic axes span the box; open axes span the particles.
struct AxisCells {
  double origin = 0.0;
  double cellSize = 1.0;
  std::int64_t count = 1;
  bool periodic = false;

  [[nodiscard]] std::int64_t rawCell(double x) const {
    return static_cast<std::int64_t>(std::floor((x - origin) / cellSize));
  }
  [[nodiscard]] std::int64_t cellOf(double x) const { return std::clamp<std::int64_t>(rawCell(x), 0, count - 1); }

  // Distinct cells holding points within `reach` of x (x and the points already in the
  // primary box): all cells once if the range wraps onto itself.
  void cellsNear(double x, double reach, std::vector<std::int64_t>& out) const {
    out.clear();
    std::int64_t first = rawCell(x - reach), last = rawCell(x + reach);
    if (periodic) {
      if (last - first + 1 >= count) {
        first = 0;
        last = count - 1;
      }
      for (std::int64_t c = first; c <= last; ++c) out.push_back(c - floorDiv(c, count) * count);
      return;
    }
    first = std::max<std::int64_t>(first, 0);
    last = std::min<std::int64_t>(last, count - 1);
    for (std::int64_t c = first; c <= last; ++c) out.push_back(c);
  }
};

// The image of p in the primary box: y first (it shifts x under Lees-Edwards), then x and z.
Vec3 wrapIntoBox(Vec3 p, const PeriodicBox& box) {
  if (box.periodic(1)) {
    const double images = std::floor((p[1] - box.lo(1)) / box.length(1));
    p[1] -= images * box.length(1);
    p[0] -= images * box.leesEdwardsOffset();
  }
  for (int a : {0, 2}) {
    if (box.periodic(a)) p[a] -= std::floor((p[a] - box.lo(a)) / box.length(a)) * box.length(a);
  }
  return p;
}

}  // namespace

std::vector<CandidatePair> findCandidatePairs(const std::vector<Vec3>& positions, const PeriodicBox& box,
                                              double cutoff) {
  if (!(cutoff >= 0.0) || !std::isfinite(cutoff)) {
    throw Error("the candidate-pair cutoff " + std::to_string(cutoff) + " must be finite and non-negative");
  }
  const std::size_t n = positions.size();
  if (n >= std::numeric_limits<std::uint32_t>::max()) {
    throw Error("the MST candidate search takes at most 2^32 - 1 particles; the frame has " + std::to_string(n));
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (!positions[k].allFinite()) throw Error("particle " + std::to_string(k) + " has a non-finite position");
  }
  std::vector<CandidatePair> pairs;
  if (n < 2) return pairs;

  std::vector<Vec3> wrapped(n);
  for (std::size_t k = 0; k < n; ++k) wrapped[k] = wrapIntoBox(positions[k], box);

  // Cells at least `cutoff` wide, so neighbours sit in adjacent cells; at most ~2 cells per
  // particle, so a sparse frame with a large box does not allocate a huge empty grid.
  std::array<AxisCells, 3> axes;
  std::array<double, 3> span{};
  for (int a = 0; a < 3; ++a) {
    AxisCells& ax = axes[static_cast<std::size_t>(a)];
    ax.periodic = box.periodic(a);
    if (ax.periodic) {
      ax.origin = box.lo(a);
      span[static_cast<std::size_t>(a)] = box.length(a);
    } else {
      double lo = wrapped[0][a], hi = lo;
      for (const Vec3& p : wrapped) {
        lo = std::min(lo, p[a]);
        hi = std::max(hi, p[a]);
      }
      ax.origin = lo;
      span[static_cast<std::size_t>(a)] = hi - lo;
    }
    const double fit = cutoff > 0.0 ? std::floor(span[static_cast<std::size_t>(a)] / cutoff) : 1.0;
    ax.count = static_cast<std::int64_t>(std::clamp(fit, 1.0, 1e6));
  }
  const double cellLimit = 2.0 * static_cast<double>(n) + 27.0;
  for (;;) {
    const double cells =
        static_cast<double>(axes[0].count) * static_cast<double>(axes[1].count) * static_cast<double>(axes[2].count);
    if (cells <= cellLimit) break;
    const double shrink = std::cbrt(cells / cellLimit);
    for (AxisCells& ax : axes) {
      ax.count = std::max<std::int64_t>(1, static_cast<std::int64_t>(static_cast<double>(ax.count) / shrink));
    }
  }
  for (std::size_t a = 0; a < 3; ++a) {
    axes[a].cellSize = span[a] > 0.0 ? span[a] / static_cast<double>(axes[a].count) : 1.0;
  }
  const std::int64_t nx = axes[0].count, ny = axes[1].count, nz = axes[2].count;

  // Counting sort of particles by cell (CSR): slots cellStart[c]..cellStart[c+1] hold the
  // particles of cell c, with their positions copied alongside so the inner loop reads memory
  // in order.
  std::vector<std::size_t> cellOfParticle(n);
  std::vector<std::size_t> cellStart(static_cast<std::size_t>(nx * ny * nz) + 1, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& p = wrapped[k];
    cellOfParticle[k] =
        static_cast<std::size_t>((axes[2].cellOf(p[2]) * ny + axes[1].cellOf(p[1])) * nx + axes[0].cellOf(p[0]));
    ++cellStart[cellOfParticle[k] + 1];
  }
  for (std::size_t c = 1; c < cellStart.size(); ++c) cellStart[c] += cellStart[c - 1];
  std::vector<std::uint32_t> slotParticle(n);
  std::vector<Vec3> slotPosition(n), slotWrapped(n);
  {
    std::vector<std::size_t> fill(cellStart.begin(), cellStart.end() - 1);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t slot = fill[cellOfParticle[k]]++;
      slotParticle[slot] = static_cast<std::uint32_t>(k);
      slotPosition[slot] = positions[k];
      slotWrapped[slot] = wrapped[k];
    }
  }

  // The search reach carries a round-off margin (wrapped positions are images of the raw ones to
  // ~1 ulp); acceptance is decided on the exact minimum-image length alone.
  const double reach = cutoff * (1.0 + 1e-9) + 1e-12 * std::max({span[0], span[1], span[2], 1.0});
  const double looseSquared = reach * reach;
  const double offset = box.leesEdwardsOffset();
  // Expected pair count for uniformly spread particles, n^2/2 (4/3 pi cutoff^3) / volume, so the
  // (tens of MB) output is allocated once rather than grown by copying.
  const double volume = std::max(span[0], cutoff) * std::max(span[1], cutoff) * std::max(span[2], cutoff);
  if (volume > 0.0) {
    const double expected =
        0.5 * static_cast<double>(n) * static_cast<double>(n) * 4.18879 * cutoff * cutoff * cutoff / volume;
    pairs.reserve(
        static_cast<std::size_t>(std::min(1.1 * expected, 0.5 * static_cast<double>(n) * static_cast<double>(n - 1))));
  }
  std::vector<std::int64_t> zCells, yCells, xCells;
  const std::size_t cellCount = cellStart.size() - 1;
  for (std::size_t cell = 0; cell < cellCount; ++cell) {
    for (std::size_t slot = cellStart[cell]; slot < cellStart[cell + 1]; ++slot) {
      const Vec3& p = slotWrapped[slot];
      const Vec3& raw = slotPosition[slot];
      const std::uint32_t i = slotParticle[slot];
      axes[2].cellsNear(p[2], reach, zCells);
      // Rows in y, each with its image count ky: a particle in a row reached across the y
      // boundary is seen through its image shifted by ky (offset, L_y, 0), so its x range moves
      // by ky offset.
      const std::int64_t firstRow = axes[1].rawCell(p[1] - reach), lastRow = axes[1].rawCell(p[1] + reach);
      const bool allRows = axes[1].periodic && lastRow - firstRow + 1 >= ny;
      axes[1].cellsNear(p[1], reach, yCells);
      for (std::size_t r = 0; r < yCells.size(); ++r) {
        const std::int64_t row = yCells[r];
        if (allRows && box.leesEdwards()) {
          // Which image is nearest depends on the particle: search the whole row.
          xCells.resize(static_cast<std::size_t>(nx));
          for (std::int64_t c = 0; c < nx; ++c) xCells[static_cast<std::size_t>(c)] = c;
        } else {
          // Without Lees-Edwards the offset is 0 and ky does not matter.
          const std::int64_t imagesInY = axes[1].periodic ? floorDiv(firstRow + static_cast<std::int64_t>(r), ny) : 0;
          axes[0].cellsNear(p[0] - static_cast<double>(imagesInY) * offset, reach, xCells);
        }
        for (const std::int64_t z : zCells) {
          for (const std::int64_t x : xCells) {
            // Each pair once: the cell search is symmetric (a pair within the cutoff is found
            // from both ends), so keep it from the end in the lower cell, or the lower slot.
            const auto other = static_cast<std::size_t>((z * ny + row) * nx + x);
            if (other < cell) continue;
            const std::size_t firstSlot = other == cell ? slot + 1 : cellStart[other];
            for (std::size_t s = firstSlot; s < cellStart[other + 1]; ++s) {
              const std::uint32_t j = slotParticle[s];
              // Lower index first, so the length is bitwise the same whichever end found it.
              const Vec3 d = i < j ? box.minimumImage(raw - slotPosition[s]) : box.minimumImage(slotPosition[s] - raw);
              const double squared = d.squaredNorm();
              if (squared > looseSquared) continue;
              const double length = std::sqrt(squared);
              if (length <= cutoff) pairs.push_back({length, std::min(i, j), std::max(i, j)});
            }
          }
        }
      }
    }
  }
  return pairs;
}

}  // namespace grainbridge::extract::structure
