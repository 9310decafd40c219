#include "extract/geometry/PairSearch.hpp"

#include <algorithm>
#include <numbers>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::geometry {

namespace {
constexpr std::size_t kNoEntry = static_cast<std::size_t>(-1);

std::int64_t floorDiv(std::int64_t a, std::int64_t n) { return a >= 0 ? a / n : -((-a + n - 1) / n); }
}  // namespace

PairSearch::PairSearch(const PeriodicBox& box, std::span<const Vec3> points, double cutoff, Lengths lengths)
    : box_(box), cutoff_(cutoff), exact_(lengths == Lengths::Exact) {
  if (!(cutoff >= 0.0) || !std::isfinite(cutoff)) {
    throw Error("pair search: the cutoff " + std::to_string(cutoff) + " must be finite and non-negative");
  }
  std::vector<Vec3> wrapped;
  wrapped.reserve(points.size());
  // Coordinates, box edges and the offset set the size of the round-off in the wrapped
  // positions and image shifts.
  double scale = std::max(1.0, std::abs(box_.leesEdwardsOffset()));
  for (int a = 0; a < 3; ++a) {
    if (box_.periodic(a)) scale = std::max(scale, box_.length()[a]);
  }
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (!points[k].allFinite()) throw Error("pair search: point " + std::to_string(k) + " has a non-finite position");
    scale = std::max(scale, points[k].cwiseAbs().maxCoeff());
    wrapped.push_back(box_.wrap(points[k]));
  }
  // Wrapped positions and image shifts are exact to a few ulp of `scale`, so for exact lengths
  // the cheap test and the cells search a little further than the cutoff; acceptance is on the
  // exact length alone.
  reach_ = exact_ ? cutoff * (1.0 + 1e-9) + 1e-12 * scale : cutoff;
  halfSquared_ = box_.maxUniqueDistance() * box_.maxUniqueDistance();

  // Periodic axes span the box; open axes span the points (contact points may sit on walls).
  Vec3 lo = box_.lo();
  extent_ = box_.length();
  for (int a = 0; a < 3; ++a) {
    if (box_.periodic(a)) continue;
    double mn = 0.0, mx = 0.0;
    if (!wrapped.empty()) {
      mn = mx = wrapped[0][a];
      for (const Vec3& p : wrapped) {
        mn = std::min(mn, p[a]);
        mx = std::max(mx, p[a]);
      }
    }
    lo[a] = mn;
    extent_[a] = mx - mn;
  }
  // Cells of about reach / 2: candidate volume (2.5 reach)^3 against 27 reach^3 for cells of the
  // reach. Coarser when that would give far more cells than points (sparse or huge boxes, tiny
  // cutoffs); coarser cells are still correct, only slower.
  const auto cap = std::max<std::int64_t>(64, 2 * static_cast<std::int64_t>(wrapped.size()));
  double cell = std::max(0.5 * reach_, 1e-12 * scale);  // not 0 for a zero cutoff
  for (;;) {
    std::int64_t total = 1;
    for (int a = 0; a < 3; ++a) {
      // Clamped in floating point: extent / cell overflows an integer for a tiny cutoff.
      const double fit = std::floor(extent_[a] / cell);
      const auto u = static_cast<std::size_t>(a);
      cells_[u] = static_cast<std::int64_t>(std::clamp(fit, 1.0, static_cast<double>(cap)));
      total = std::min(total * cells_[u], cap + 1);
    }
    if (total <= cap) break;
    cell *= 1.25;
  }
  origin_ = lo;
  // A minimum-image component on a periodic axis is at most half the box (plus round-off in the
  // positions), so no search needs to reach further than that, and a cutoff many boxes long
  // costs no more than one of half the box.
  const double margin = exact_ ? 1e-12 * scale : 0.0;
  for (int a = 0; a < 3; ++a) {
    const auto u = static_cast<std::size_t>(a);
    // Open axes: cells of exactly `cell`, the last one open-ended (indices are clamped).
    cellSize_[a] = box_.periodic(a) ? extent_[a] / static_cast<double>(cells_[u]) : cell;
    axisReach_[a] = box_.periodic(a) ? std::min(reach_, 0.5 * extent_[a] + margin) : reach_;
    cellReach_[u] =
        std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(axisReach_[a] / cellSize_[a] * (1.0 - 1e-12))));
  }

  // Counting sort of the points by cell (CSR), positions copied alongside so the inner loop
  // reads memory in order.
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
  wrapped_.resize(wrapped.size());
  given_.resize(wrapped.size());
  original_.resize(wrapped.size());
  inBox_.assign(nCells, 1);
  std::vector<std::size_t> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (std::size_t i = 0; i < wrapped.size(); ++i) {
    const std::size_t slot = fill[cellOf[i]]++;
    wrapped_[slot] = wrapped[i];
    given_[slot] = points[i];
    original_[slot] = i;
    // Wrapping subtracts zero from a point already in the box, which leaves it bitwise as given.
    if (wrapped[i] != points[i]) inBox_[cellOf[i]] = 0;
  }
}

std::size_t PairSearch::expectedPairCount() const {
  const double n = static_cast<double>(original_.size());
  const double volume = std::max(extent_[0], cutoff_) * std::max(extent_[1], cutoff_) * std::max(extent_[2], cutoff_);
  if (!(volume > 0.0)) return 0;
  // n^2 / 2 times the fraction of the volume in a sphere of the cutoff, at most all pairs.
  const double expected = 0.5 * n * n * (4.0 / 3.0 * std::numbers::pi) * cutoff_ * cutoff_ * cutoff_ / volume;
  return static_cast<std::size_t>(std::min(1.1 * expected, 0.5 * n * std::max(n - 1.0, 0.0)));
}

void PairSearch::neighbours(std::size_t c, std::vector<Neighbour>& out, std::vector<std::size_t>& entryOf) const {
  for (const Neighbour& n : out) entryOf[n.cell] = kNoEntry;
  out.clear();
  const auto nx = cells_[0], ny = cells_[1];
  const auto flat = static_cast<std::int64_t>(c);
  const std::int64_t cx = flat % nx, cy = (flat / nx) % ny, cz = flat / (nx * ny);
  const Vec3& L = box_.length();
  const double offset = box_.leesEdwardsOffset();
  const AxisRange zs = axisRange(2, cz - cellReach_[2], cz + cellReach_[2]);
  const AxisRange ys = axisRange(1, cy - cellReach_[1], cy + cellReach_[1]);
  const AxisRange xs = axisRange(0, cx - cellReach_[0], cx + cellReach_[0]);
  for (std::size_t iz = 0; iz < zs.size; ++iz) {
    const auto [wz, kz] = zs.cells[iz];
    for (std::size_t iy = 0; iy < ys.size; ++iy) {
      const auto [wy, ky] = ys.cells[iy];
      // A y cell reached across the top (ky = +1) is the image displaced by +offset in x, so its
      // points that are near cell c sit at x - offset: shift the x range by -ky offset.
      AxisRange shifted;
      if (ky != 0 && offset != 0.0) {
        const double lo = origin_[0] + static_cast<double>(cx) * cellSize_[0] - static_cast<double>(ky) * offset;
        shifted = axisRange(
            0, static_cast<std::int64_t>(std::floor((lo - axisReach_[0] - origin_[0]) / cellSize_[0])),
            static_cast<std::int64_t>(std::floor((lo + cellSize_[0] + axisReach_[0] - origin_[0]) / cellSize_[0])));
      }
      const AxisRange& row = ky != 0 && offset != 0.0 ? shifted : xs;
      for (std::size_t ix = 0; ix < row.size; ++ix) {
        const auto [wx, kx] = row.cells[ix];
        const auto cell = static_cast<std::size_t>((wz * ny + wy) * nx + wx);
        if (cell < c) continue;  // the pair (c', c) is visited from c'
        if (cellStart_[cell] == cellStart_[cell + 1]) continue;
        const Vec3 shift(static_cast<double>(kx) * L[0] + static_cast<double>(ky) * offset,
                         static_cast<double>(ky) * L[1], static_cast<double>(kz) * L[2]);
        // One entry per cell; a cell reached through two different images is ambiguous.
        if (entryOf[cell] == kNoEntry) {
          entryOf[cell] = out.size();
          out.push_back({cell, shift, Image::Fixed});
        } else if (!(out[entryOf[cell]].shift - shift).isZero(0.0)) {
          out[entryOf[cell]].image = Image::Ambiguous;
        }
      }
    }
  }
  // In cell order, so that sums over the pairs (the correlation bins) always round the same
  // way. The ranges above already come in cell order; only a Lees-Edwards row reached through
  // two y images can add cells out of it.
  const auto byCell = [](const Neighbour& a, const Neighbour& b) { return a.cell < b.cell; };
  if (!std::is_sorted(out.begin(), out.end(), byCell)) std::sort(out.begin(), out.end(), byCell);
  for (Neighbour& n : out) {
    if (n.image == Image::Ambiguous) continue;
    const bool shifted = !n.shift.isZero(0.0);
    if (shifted && n.cell == c) {
      // The cell itself with a non-zero image shift only (one cell along a periodic axis) is
      // also ambiguous: a half-visited pair (a, b > a) is only symmetric without a shift.
      n.image = Image::Ambiguous;
    } else if (!shifted && inBox_[c] && inBox_[n.cell]) {
      n.image = Image::Direct;
    }
  }
}

PairSearch::AxisRange PairSearch::axisRange(int axis, std::int64_t first, std::int64_t last) const {
  const auto n = cells_[static_cast<std::size_t>(axis)];
  AxisRange range;
  if (!box_.periodic(axis)) {
    for (std::int64_t r = std::max<std::int64_t>(first, 0); r <= std::min(last, n - 1); ++r) {
      range.cells[range.size++] = {r, 0};
    }
    return range;
  }
  // Cells are at least reach / 2 wide, so a range is at most 2 * 2 + 2 cells (a Lees-Edwards
  // row starts mid-cell).
  GB_ASSERT(last - first + 1 <= static_cast<std::int64_t>(range.cells.size()), "pair search: neighbour range too long");
  for (std::int64_t r = first; r <= last; ++r) {
    const std::int64_t k = floorDiv(r, n);
    // Insertion by wrapped index, images of one cell in raw order.
    std::size_t at = range.size++;
    for (; at > 0 && range.cells[at - 1].first > r - k * n; --at) range.cells[at] = range.cells[at - 1];
    range.cells[at] = {r - k * n, k};
  }
  return range;
}

}  // namespace grainbridge::extract::geometry
