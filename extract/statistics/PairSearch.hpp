#pragma once
// All pairs of points closer than r_max, under the minimum image of the frame's box, by a
// cell list. Eq. 6.12 on 50k contacts is a sum over ~1e9 pairs if done directly; with cells the
// work is N times the number of points within r_max.
//
// Cells are about r_max/2 wide and visited in pairs (c, c' >= c), so no candidate pair is
// looked at twice. For each neighbour cell the periodic (and Lees-Edwards) image shift is
// fixed, so a candidate costs one subtraction and a squared norm; only when a small box makes
// one cell reachable through two different images (fewer cells along an axis than the
// neighbour range) does a cell pair fall back to the general minimum image per pair.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/Types.hpp"
#include "core/data/Domain.hpp"
#include "extract/statistics/MinimumImage.hpp"

namespace grainbridge::extract::statistics {

class PairSearch {
 public:
  // Throws grainbridge::Error if r_max is not positive or exceeds half a periodic box edge
  // (the minimum image would no longer be unique), or a point is not finite.
  PairSearch(const core::data::Domain& domain, std::span<const Vec3> points, double rMax);

  // Calls visit(i, j, r) once for every unordered pair i < j (indices into the points given to
  // the constructor) with minimum-image distance r < r_max.
  template <class Visit>
  void forEachPair(Visit&& visit) const;

  [[nodiscard]] const MinimumImage& image() const { return image_; }
  [[nodiscard]] std::size_t size() const { return original_.size(); }

 private:
  struct Neighbour {
    std::size_t cell;
    Vec3 shift;  // image of the neighbour cell's points: p + shift
    bool exact;  // false: reachable through several images, use the general minimum image
  };
  // Neighbour cells c' >= c of cell c that can hold a point within r_max of a point in c.
  void neighbours(std::size_t c, std::vector<Neighbour>& out) const;

  MinimumImage image_;
  double rMax_;
  Vec3 origin_, cellSize_;
  std::array<std::int64_t, 3> cells_{};
  std::array<std::int64_t, 3> reach_{};  // neighbour range in cells: ceil(r_max / cell size)
  std::vector<std::size_t> cellStart_;   // CSR: points of cell c are [start[c], start[c+1])
  std::vector<Vec3> sorted_;             // wrapped points ordered by cell
  std::vector<std::size_t> original_;    // sorted index -> constructor index
};

template <class Visit>
void PairSearch::forEachPair(Visit&& visit) const {
  const double r2max = rMax_ * rMax_;
  std::vector<Neighbour> near;
  const std::size_t nCells = cellStart_.size() - 1;
  auto emit = [&](std::size_t a, std::size_t b, double r2) {
    const std::size_t i = original_[a], j = original_[b];
    visit(i < j ? i : j, i < j ? j : i, std::sqrt(r2));
  };
  for (std::size_t c = 0; c < nCells; ++c) {
    const std::size_t s0 = cellStart_[c], e0 = cellStart_[c + 1];
    if (s0 == e0) continue;
    neighbours(c, near);
    for (const Neighbour& n : near) {
      const std::size_t s1 = cellStart_[n.cell], e1 = cellStart_[n.cell + 1];
      if (s1 == e1) continue;
      const bool same = n.cell == c;
      for (std::size_t a = s0; a < e0; ++a) {
        const Vec3 pa = sorted_[a];
        const Vec3 pi = pa - n.shift;
        for (std::size_t b = same ? a + 1 : s1; b < e1; ++b) {
          // Hot loop: 3 subtractions, a squared norm and a compare per candidate.
          const double r2 = n.exact ? (pi - sorted_[b]).squaredNorm() : image_.separation(pa, sorted_[b]).squaredNorm();
          if (r2 < r2max) emit(a, b, r2);
        }
      }
    }
  }
}

}  // namespace grainbridge::extract::statistics
