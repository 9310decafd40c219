#include "core/grid/CellGrid.hpp"

#include <algorithm>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::core::grid {

namespace {
const char* axisName(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }
}  // namespace

CellGrid::CellGrid(const Vec3& lo, const Vec3& hi, const std::array<int, 3>& counts,
                   const std::array<bool, 3>& periodic)
    : lo_(lo), hi_(hi), spacing_(Vec3::Zero()), inverseSpacing_(Vec3::Zero()), counts_(counts), periodic_(periodic) {
  for (int a = 0; a < 3; ++a) {
    const auto s = static_cast<std::size_t>(a);
    if (!(hi[a] > lo[a]) || !std::isfinite(lo[a]) || !std::isfinite(hi[a])) {
      throw Error(std::string("cell grid: ") + axisName(a) + " range [" + std::to_string(lo[a]) + ", " +
                  std::to_string(hi[a]) + "] is empty; hi must exceed lo");
    }
    if (counts[s] < 1) {
      throw Error(std::string("cell grid: ") + std::to_string(counts[s]) + " cells along " + axisName(a) +
                  ", expected at least 1");
    }
    spacing_[a] = (hi[a] - lo[a]) / counts[s];
    inverseSpacing_[a] = 1.0 / spacing_[a];
  }
}

CellGrid CellGrid::overDomain(const data::Domain& domain, const std::array<int, 3>& counts) {
  CellGrid g(domain.lo, domain.hi, counts, domain.periodic);
  return domain.leesEdwardsOffset != 0.0 ? g.withLeesEdwardsOffset(domain.leesEdwardsOffset) : g;
}

CellGrid CellGrid::withLeesEdwardsOffset(double offset) const {
  if (offset != 0.0 && !(periodic_[0] && periodic_[1])) {
    throw Error("cell grid: a Lees-Edwards offset " + std::to_string(offset) +
                " needs a grid periodic in x (flow) and y (gradient)");
  }
  CellGrid g = *this;
  g.leesEdwardsOffset_ = offset;
  return g;
}

std::size_t CellGrid::cellCount() const {
  return static_cast<std::size_t>(counts_[0]) * static_cast<std::size_t>(counts_[1]) *
         static_cast<std::size_t>(counts_[2]);
}

CellIndex CellGrid::cellIndex(std::size_t flat) const {
  const auto nx = static_cast<std::size_t>(counts_[0]);
  const auto ny = static_cast<std::size_t>(counts_[1]);
  return {static_cast<int>(flat % nx), static_cast<int>((flat / nx) % ny), static_cast<int>(flat / (nx * ny))};
}

std::optional<CellIndex> CellGrid::cellOf(const Vec3& point) const {
  // Inside the box (nearly every point) there is nothing to fold, and what follows reduces to
  // the cell by axisCell, capped at the last cell.
  const Vec3 r = point - lo_;
  if ((r.array() >= 0.0).all() && (r.array() < (hi_ - lo_).array()).all()) {
    return CellIndex{std::min(axisCell(0, point[0]), counts_[0] - 1), std::min(axisCell(1, point[1]), counts_[1] - 1),
                     std::min(axisCell(2, point[2]), counts_[2] - 1)};
  }
  Vec3 p = point;
  const Vec3 len = length();
  if (periodic_[1]) {
    // Across the shearing boundary a point re-enters displaced by the offset (Domain.hpp).
    const double m = imageOf(1, p[1]);
    p[1] -= m * len[1];
    p[0] -= m * leesEdwardsOffset_;
  }
  std::array<int, 3> idx{};
  for (int a = 0; a < 3; ++a) {
    const auto s = static_cast<std::size_t>(a);
    if (periodic_[s]) p[a] -= len[a] * imageOf(a, p[a]);
    int i = axisCell(a, p[a]);
    if (periodic_[s]) {
      // floor round-off can put a point a hair below hi into cell n
      i = std::min(std::max(i, 0), counts_[s] - 1);
    } else {
      if (p[a] < lo_[a] || p[a] > hi_[a]) return std::nullopt;
      i = std::min(i, counts_[s] - 1);
    }
    idx[s] = i;
  }
  return CellIndex{idx[0], idx[1], idx[2]};
}

Vec3 CellGrid::cellLo(const CellIndex& c) const {
  return lo_ + Vec3(c.i * spacing_[0], c.j * spacing_[1], c.k * spacing_[2]);
}

Vec3 CellGrid::cellCentre(const CellIndex& c) const {
  return lo_ + Vec3((c.i + 0.5) * spacing_[0], (c.j + 0.5) * spacing_[1], (c.k + 0.5) * spacing_[2]);
}

data::GridGeometry CellGrid::geometry() const {
  data::GridGeometry g;
  g.origin = lo_;
  g.spacing = spacing_;
  g.cells = counts_;
  return g;
}

}  // namespace grainbridge::core::grid
