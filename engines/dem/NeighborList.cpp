#include "engines/dem/NeighborList.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/Error.hpp"

namespace grainbridge::dem {

namespace {

struct PairKey {
  std::int64_t low;
  std::int64_t high;
  bool operator==(const PairKey&) const = default;
};
struct PairKeyHash {
  std::size_t operator()(const PairKey& k) const {
    const auto a = static_cast<std::uint64_t>(k.low) * 0x9E3779B97F4A7C15ULL;
    return static_cast<std::size_t>(a ^
                                    (static_cast<std::uint64_t>(k.high) + 0x632BE59BD9B4E019ULL + (a << 6) + (a >> 2)));
  }
};

}  // namespace

std::vector<PairHistory> NeighborList::exportHistory() const {
  std::vector<PairHistory> out;
  const std::size_t nOld = offset_.empty() ? 0 : offset_.size() - 1;
  for (std::size_t i = 0; i < nOld; ++i) {
    for (std::size_t s = offset_[i]; s < offset_[i + 1]; ++s) {
      if (history_[s].isZero(0.0)) continue;
      const std::int64_t a = idsAtBuild_[i];
      const std::int64_t b = idsAtBuild_[partner_[s]];
      out.push_back({std::min(a, b), std::max(a, b), a < b ? history_[s] : Vec3(-history_[s])});
    }
  }
  return out;
}

double NeighborList::gridCells(const Vec3& lo, const Vec3& hi, double cutoff) {
  double cells = 1.0;
  for (int a = 0; a < 3; ++a) cells *= std::max(1.0, std::floor((hi[a] - lo[a] + 2.0 * cutoff) / cutoff));
  return cells;
}

void NeighborList::build(const Particles& p, const Vec3& lo, const Vec3& hi, double cutoff, double skin,
                         const std::vector<PairHistory>* seed) {
  // 1. Remember the history of pairs in contact, keyed by ids in (low, high) orientation.
  std::unordered_map<PairKey, Vec3, PairKeyHash> carried;
  for (const auto& h : seed != nullptr ? *seed : exportHistory()) carried.emplace(PairKey{h.low, h.high}, h.ut);

  // 2. Counting sort of all particles (owned and ghost) into cells of side >= cutoff.
  const Vec3 gridLo = lo - Vec3::Constant(cutoff);
  const Vec3 extent = (hi - lo) + Vec3::Constant(2.0 * cutoff);
  GB_ASSERT(gridCells(lo, hi, cutoff) <= kMaxGridCells, "setups with larger grids are refused at set-up");
  Vec3i cells;
  for (int a = 0; a < 3; ++a) cells[a] = std::max(1, static_cast<int>(std::floor(extent[a] / cutoff)));
  const Vec3 cellSize = extent.cwiseQuotient(cells.cast<double>());
  const std::size_t nCells = static_cast<std::size_t>(cells[0]) * cells[1] * cells[2];
  const std::size_t n = p.size();
  cellOf_.resize(n);
  cellStart_.assign(nCells + 1, 0);
  auto cellIndex = [&](const Vec3i& c) { return (static_cast<std::size_t>(c[2]) * cells[1] + c[1]) * cells[0] + c[0]; };
  auto cellCoord = [&](const Vec3& x) {
    Vec3i c;
    for (int a = 0; a < 3; ++a) c[a] = std::clamp(static_cast<int>((x[a] - gridLo[a]) / cellSize[a]), 0, cells[a] - 1);
    return c;
  };
  for (std::size_t i = 0; i < n; ++i) {
    cellOf_[i] = static_cast<std::uint32_t>(cellIndex(cellCoord(p.x[i])));
    ++cellStart_[cellOf_[i] + 1];
  }
  for (std::size_t c = 0; c < nCells; ++c) cellStart_[c + 1] += cellStart_[c];
  cellItems_.resize(n);
  {
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) cellItems_[fill[cellOf_[i]]++] = static_cast<std::uint32_t>(i);
  }

  // 3. Pairs: for each owned particle, the 27 surrounding cells; test r^2 < (a_i + a_j + skin)^2.
  offset_.assign(p.nOwned + 1, 0);
  partner_.clear();
  candidates_.clear();
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    const Vec3i ci = cellCoord(p.x[i]);
    const Vec3& xi = p.x[i];
    const bool iFrozen = p.isFrozen(i);
    const double reachI = p.radius[i] + skin;
    for (int dz = -1; dz <= 1; ++dz) {
      const int cz = ci[2] + dz;
      if (cz < 0 || cz >= cells[2]) continue;
      for (int dy = -1; dy <= 1; ++dy) {
        const int cy = ci[1] + dy;
        if (cy < 0 || cy >= cells[1]) continue;
        for (int dx = -1; dx <= 1; ++dx) {
          const int cx = ci[0] + dx;
          if (cx < 0 || cx >= cells[0]) continue;
          const std::size_t c = cellIndex(Vec3i(cx, cy, cz));
          candidates_.insert(candidates_.end(), cellItems_.begin() + cellStart_[c],
                             cellItems_.begin() + cellStart_[c + 1]);
        }
      }
    }
    // The candidates in cell order, each kept or not without a branch: whether j comes after i
    // (each pair once) is a coin toss per candidate, and as a branch its mispredictions were
    // most of a dense box's build (perf: a pressure-controlled box rebuilds every 10 steps).
    // Every candidate is written and the count moves by the test; the pairs and their order are
    // those of a loop that pushed the kept ones.
    const std::size_t first = partner_.size();
    partner_.resize(first + candidates_.size());
    std::size_t kept = first;
    const std::int64_t idI = p.id[i];
    for (const std::uint32_t j : candidates_) {
      const bool after = j < p.nOwned ? j > i : p.id[j] > idI;  // each pair once
      const bool bothFrozen = iFrozen && p.isFrozen(j);
      const double reach = reachI + p.radius[j];
      const bool near = (p.x[j] - xi).squaredNorm() < reach * reach;
      partner_[kept] = j;
      kept += static_cast<std::size_t>(after & near & !bothFrozen);
    }
    partner_.resize(kept);
    candidates_.clear();
    offset_[i + 1] = partner_.size();
    // Ascending partner order makes the force sum independent of cell layout details.
    std::sort(partner_.begin() + static_cast<std::ptrdiff_t>(offset_[i]), partner_.end());
  }

  // 4. Carry history over to the new slots.
  history_.assign(partner_.size(), Vec3::Zero());
  if (!carried.empty()) {
    for (std::size_t i = 0; i < p.nOwned; ++i) {
      for (std::size_t s = offset_[i]; s < offset_[i + 1]; ++s) {
        const std::int64_t a = p.id[i];
        const std::int64_t b = p.id[partner_[s]];
        auto it = carried.find(PairKey{std::min(a, b), std::max(a, b)});
        if (it != carried.end()) history_[s] = a < b ? it->second : Vec3(-it->second);
      }
    }
  }
  x0_.assign(p.x.begin(), p.x.begin() + static_cast<std::ptrdiff_t>(p.nOwned));
  idsAtBuild_ = p.id;
  ++builds_;
}

void NeighborList::buildInner(const Particles& p, double innerSkin) {
  const std::size_t n = offset_.size() - 1;
  GB_ASSERT(n == p.nOwned, "inner list built over another particle set");
  innerOffset_.assign(n + 1, 0);
  innerPartner_.clear();
  innerSlot_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& xi = p.x[i];
    const double reachI = p.radius[i] + innerSkin;
    for (std::size_t s = offset_[i]; s < offset_[i + 1]; ++s) {
      const std::uint32_t j = partner_[s];
      const double reach = reachI + p.radius[j];
      if ((p.x[j] - xi).squaredNorm() < reach * reach) {
        innerPartner_.push_back(j);
        innerSlot_.push_back(s);
      } else {
        history_[s].setZero();
      }
    }
    innerOffset_[i + 1] = innerPartner_.size();
  }
  x1_.assign(p.x.begin(), p.x.begin() + static_cast<std::ptrdiff_t>(n));
  ++innerBuilds_;
}

}  // namespace grainbridge::dem
