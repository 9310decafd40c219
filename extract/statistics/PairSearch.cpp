#include "extract/statistics/PairSearch.hpp"

#include <algorithm>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::statistics {

namespace {
std::int64_t floorDiv(std::int64_t a, std::int64_t n) { return a >= 0 ? a / n : -((-a + n - 1) / n); }
}  // namespace

PairSearch::PairSearch(const core::data::Domain& domain, std::span<const Vec3> points, double rMax)
    : image_(domain), rMax_(rMax) {
  if (!(rMax > 0.0) || !std::isfinite(rMax)) {
    throw Error("pair search: r_max must be positive and finite, got " + std::to_string(rMax));
  }
  if (rMax > image_.maxUniqueDistance()) {
    throw Error("pair search: r_max = " + std::to_string(rMax) + " exceeds half the shortest periodic box edge (" +
                std::to_string(image_.maxUniqueDistance()) + "); the minimum image would not be unique");
  }
  std::vector<Vec3> wrapped;
  wrapped.reserve(points.size());
  for (const Vec3& p : points) {
    if (!p.allFinite()) throw Error("pair search: a point position is not finite");
    wrapped.push_back(image_.wrap(p));
  }
  // Periodic axes span the box; open axes span the points (contact points may sit on walls).
  Vec3 lo = image_.lo(), extent = image_.length();
  for (int a = 0; a < 3; ++a) {
    if (image_.periodic(a)) continue;
    double mn = 0.0, mx = 0.0;
    if (!wrapped.empty()) {
      mn = mx = wrapped[0][a];
      for (const Vec3& p : wrapped) {
        mn = std::min(mn, p[a]);
        mx = std::max(mx, p[a]);
      }
    }
    lo[a] = mn;
    extent[a] = mx - mn;
  }
  // Cells of about r_max / 2: candidate volume (2.5 r_max)^3 against 27 r_max^3 for cells of
  // r_max. Coarser when that would give far more cells than points (sparse or huge boxes).
  const auto cap = std::max<std::int64_t>(64, 2 * static_cast<std::int64_t>(wrapped.size()));
  double cell = 0.5 * rMax;
  for (;;) {
    std::int64_t total = 1;
    for (int a = 0; a < 3; ++a) {
      cells_[static_cast<std::size_t>(a)] = std::max<std::int64_t>(1, static_cast<std::int64_t>(extent[a] / cell));
      total *= cells_[static_cast<std::size_t>(a)];
    }
    if (total <= cap) break;
    cell *= 1.25;  // coarser cells are still correct, only slower
  }
  origin_ = lo;
  for (int a = 0; a < 3; ++a) {
    const auto u = static_cast<std::size_t>(a);
    // Open axes: cells of exactly `cell`, the last one open-ended (indices are clamped).
    cellSize_[a] = image_.periodic(a) ? extent[a] / static_cast<double>(cells_[u]) : cell;
    reach_[u] = static_cast<std::int64_t>(std::ceil(rMax / cellSize_[a] * (1.0 - 1e-12)));
  }
  const auto nCells = static_cast<std::size_t>(cells_[0] * cells_[1] * cells_[2]);
  std::vector<std::size_t> cellOf(wrapped.size());
  cellStart_.assign(nCells + 1, 0);
  for (std::size_t i = 0; i < wrapped.size(); ++i) {
    std::size_t flat = 0;
    for (int a = 2; a >= 0; --a) {
      const auto n = cells_[static_cast<std::size_t>(a)];
      auto c = static_cast<std::int64_t>(std::floor((wrapped[i][a] - origin_[a]) / cellSize_[a]));
      c = std::clamp<std::int64_t>(c, 0, n - 1);
      flat = flat * static_cast<std::size_t>(n) + static_cast<std::size_t>(c);
    }
    cellOf[i] = flat;
    ++cellStart_[flat + 1];
  }
  for (std::size_t c = 0; c < nCells; ++c) cellStart_[c + 1] += cellStart_[c];
  sorted_.resize(wrapped.size());
  original_.resize(wrapped.size());
  std::vector<std::size_t> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (std::size_t i = 0; i < wrapped.size(); ++i) {
    const std::size_t slot = fill[cellOf[i]]++;
    sorted_[slot] = wrapped[i];
    original_[slot] = i;
  }
}

void PairSearch::neighbours(std::size_t c, std::vector<Neighbour>& out) const {
  out.clear();
  const auto nx = cells_[0], ny = cells_[1], nz = cells_[2];
  const auto flat = static_cast<std::int64_t>(c);
  const std::int64_t cx = flat % nx, cy = (flat / nx) % ny, cz = flat / (nx * ny);
  const Vec3& L = image_.length();
  // Raw (unwrapped) index range along axis a around cell index ci, clamped on open axes.
  auto range = [&](int a, std::int64_t ci, std::int64_t& first, std::int64_t& last) {
    const auto u = static_cast<std::size_t>(a);
    first = ci - reach_[u];
    last = ci + reach_[u];
    if (!image_.periodic(a)) {
      first = std::max<std::int64_t>(first, 0);
      last = std::min<std::int64_t>(last, cells_[u] - 1);
    }
  };
  std::int64_t y0, y1, z0, z1;
  range(1, cy, y0, y1);
  range(2, cz, z0, z1);
  for (std::int64_t zr = z0; zr <= z1; ++zr) {
    const std::int64_t kz = image_.periodic(2) ? floorDiv(zr, nz) : 0;
    const std::int64_t wz = zr - kz * nz;
    for (std::int64_t yr = y0; yr <= y1; ++yr) {
      const std::int64_t ky = image_.periodic(1) ? floorDiv(yr, ny) : 0;
      const std::int64_t wy = yr - ky * ny;
      // A y cell reached across the top (ky = +1) is the image displaced by +offset in x, so its
      // points that are near cell c sit at x - offset: shift the x range by -ky offset.
      std::int64_t x0, x1;
      if (ky != 0 && image_.shearOffset() != 0.0) {
        const double lo =
            origin_[0] + static_cast<double>(cx) * cellSize_[0] - static_cast<double>(ky) * image_.shearOffset();
        x0 = static_cast<std::int64_t>(std::floor((lo - rMax_ - origin_[0]) / cellSize_[0]));
        x1 = static_cast<std::int64_t>(std::floor((lo + cellSize_[0] + rMax_ - origin_[0]) / cellSize_[0]));
      } else {
        range(0, cx, x0, x1);
      }
      for (std::int64_t xr = x0; xr <= x1; ++xr) {
        const std::int64_t kx = image_.periodic(0) ? floorDiv(xr, nx) : 0;
        const std::int64_t wx = xr - kx * nx;
        const auto cell = static_cast<std::size_t>((wz * ny + wy) * nx + wx);
        if (cell < c) continue;  // the pair (c', c) is visited from c'
        const Vec3 shift(static_cast<double>(kx) * L[0] + static_cast<double>(ky) * image_.shearOffset(),
                         static_cast<double>(ky) * L[1], static_cast<double>(kz) * L[2]);
        out.push_back({cell, shift, true});
      }
    }
  }
  // One entry per cell; a cell reached through two different images is ambiguous.
  std::sort(out.begin(), out.end(), [](const Neighbour& a, const Neighbour& b) { return a.cell < b.cell; });
  std::size_t w = 0;
  for (std::size_t r = 0; r < out.size(); ++r) {
    if (w > 0 && out[w - 1].cell == out[r].cell) {
      if (!(out[w - 1].shift - out[r].shift).isZero(0.0)) out[w - 1].exact = false;
      continue;
    }
    out[w++] = out[r];
  }
  out.resize(w);
  // The cell itself with a non-zero image shift only (one cell along a periodic axis) is also
  // ambiguous: its own points pair through the general minimum image.
  for (Neighbour& n : out) {
    if (n.cell == c && !n.shift.isZero(0.0)) n.exact = false;
  }
}

}  // namespace grainbridge::extract::statistics
