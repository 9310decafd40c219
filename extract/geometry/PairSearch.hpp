#pragma once
// All pairs of points within a cutoff of each other under the minimum image of a frame's box
// (PeriodicBox: periodic and Lees-Edwards images), by a cell list. Eq. 6.12 on 50k contacts is
// a sum over ~1e9 pairs if done directly, and so would be the MST candidate list; with cells the
// work is N times the number of points within the cutoff.
//
// Cells are about cutoff/2 wide and visited in pairs (c, c' >= c), so no candidate pair is
// looked at twice: the candidate volume is (2.5 cutoff)^3 against 27 cutoff^3 for cells of the
// cutoff. For each neighbour cell the periodic (and Lees-Edwards) image shift is fixed, so
// rejecting a candidate costs one subtraction and a squared norm on the wrapped positions; only
// when a small box makes one cell reachable through two different images (fewer cells along an
// axis than the neighbour range, e.g. a cutoff past half the box) does a cell pair fall back to
// the minimum image of every pair.
//
// Two ways to measure, chosen once per search (Lengths):
//  - Exact (the MST): lengths never depend on the cell layout. They are
//    |box.minimumImage(p_i - p_j)| of the positions as given, bit for bit what a plain loop
//    over i < j computes (the minimum image is odd in d bit for bit, so neither end has to come
//    first), and a pair is kept if that is <= cutoff; so they do not depend on the cutoff
//    either, and ties in the MST stay ties. Cells and the cheap test carry a round-off margin,
//    and what passes is measured again that way, except where that would repeat the test's
//    arithmetic exactly: two cells without image shift whose points all lie in the box
//    (wrapping left them bitwise as given).
//  - RoundOff (binned statistics): the length the cheap test computed from the wrapped
//    positions and the image shift, the same to a few ulp, and no margin, so a pair within a
//    few ulp of the cutoff may fall either side. Bins never look at the last bits, and this
//    saves measuring again (contact points often lie just outside the box, so few of their
//    cells qualify for the exact shortcut) and keeps cells of exactly cutoff/2: a margin makes
//    a box of exactly two cutoffs (correlations capped at half the box) three cells wide, where
//    every cell is reached through two images.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "core/Types.hpp"
#include "extract/geometry/PeriodicBox.hpp"

namespace grainbridge::extract::geometry {

class PairSearch {
 public:
  // How lengths are measured (see the top of this file).
  enum class Lengths {
    Exact,     // |minimumImage(p_i - p_j)| bit for bit: ties stay ties (the MST)
    RoundOff,  // the same within a few ulp, cheaper (binned statistics)
  };

  // Any cutoff is allowed, also past half the box (the minimum image is then still the one of
  // PeriodicBox::minimumImage, found once per pair). Throws grainbridge::Error for a negative or
  // non-finite cutoff or a non-finite point.
  PairSearch(const PeriodicBox& box, std::span<const Vec3> points, double cutoff, Lengths lengths = Lengths::Exact);

  // Calls visit(i, j, r) exactly once for every unordered pair i < j (indices into the points
  // given to the constructor) with r = |minimumImage(p_i - p_j)| <= cutoff, r measured as the
  // constructor was told. Pairs come cell by cell, in an order fixed by the points and the
  // cutoff, so sums over them are reproducible to the bit.
  template <class Visit>
  void forEachPair(Visit&& visit) const;

  // Pairs expected for points spread uniformly over the searched volume, for callers that
  // collect the pairs and would rather allocate once than grow by copying.
  [[nodiscard]] std::size_t expectedPairCount() const;

 private:
  // How the pairs between a cell and one of its neighbours are measured.
  enum class Image : std::uint8_t {
    Direct,     // no shift, points as given: the test's difference is the minimum image
    Fixed,      // one image shift: test on the wrapped positions, then measure as given
    Ambiguous,  // reachable through several images: measure every pair as given
  };
  struct Neighbour {
    std::size_t cell;
    Vec3 shift;  // image of the neighbour cell's points: p + shift
    Image image;
  };
  // Non-empty neighbour cells c' >= c of cell c that can hold a point within the search reach of
  // a point in c, each once, in cell order. entryOf (one per cell, all size_t(-1) on the first
  // call) is scratch that finds a cell already listed without searching.
  void neighbours(std::size_t c, std::vector<Neighbour>& out, std::vector<std::size_t>& entryOf) const;
  // The cells of the raw (unwrapped) index range [first, last] along one axis as (wrapped index,
  // image count), ordered by wrapped index; clamped to the grid on an open axis.
  struct AxisRange {
    std::array<std::pair<std::int64_t, std::int64_t>, 8> cells{};
    std::size_t size = 0;
  };
  [[nodiscard]] AxisRange axisRange(int axis, std::int64_t first, std::int64_t last) const;

  PeriodicBox box_;
  double cutoff_;
  bool exact_;          // Lengths::Exact
  double reach_;        // cutoff (plus a round-off margin if exact_): the cheap test and the cells use it
  double halfSquared_;  // (half the shortest periodic edge)^2: shorter differences need no image
  Vec3 origin_, extent_, cellSize_;
  Vec3 axisReach_;  // reach_, or at most about half the box on a periodic axis
  std::array<std::int64_t, 3> cells_{};
  std::array<std::int64_t, 3> cellReach_{};  // neighbour range in cells: ceil(axisReach / cell size)
  std::vector<std::size_t> cellStart_;       // CSR: points of cell c are [start[c], start[c+1])
  std::vector<Vec3> wrapped_;                // wrapped points ordered by cell
  std::vector<Vec3> given_;                  // the same points as given, for the exact lengths
  std::vector<char> inBox_;                  // per cell: every point lies in the box as given
  std::vector<std::size_t> original_;        // cell-ordered index -> constructor index
};

template <class Visit>
void PairSearch::forEachPair(Visit&& visit) const {
  // Locals, not members: visit may write anywhere as far as the compiler knows, and would make it
  // reload every member after each call.
  const PeriodicBox box = box_;
  const double cutoff = cutoff_, halfSquared = halfSquared_, reachSquared = reach_ * reach_;
  const Vec3* const wrapped = wrapped_.data();
  const Vec3* const given = given_.data();
  const std::size_t* const original = original_.data();
  const std::size_t* const cellStart = cellStart_.data();
  std::vector<Neighbour> near;
  const std::size_t nCells = cellStart_.size() - 1;
  std::vector<std::size_t> entryOf(nCells, static_cast<std::size_t>(-1));
  for (std::size_t c = 0; c < nCells; ++c) {
    const std::size_t s0 = cellStart[c], e0 = cellStart[c + 1];
    if (s0 == e0) continue;
    neighbours(c, near, entryOf);
    for (const Neighbour& n : near) {
      const std::size_t s1 = cellStart[n.cell], e1 = cellStart[n.cell + 1];
      const bool same = n.cell == c;
      // Whether the test's own difference gives the length (one branch per candidate, always
      // the same way: three loops would each inline the caller's visit, or none would).
      const bool fromTest = n.image == Image::Direct || (!exact_ && n.image == Image::Fixed);
      const double testSquared = n.image == Image::Ambiguous ? std::numeric_limits<double>::infinity() : reachSquared;
      for (std::size_t a = s0; a < e0; ++a) {
        const std::size_t i = original[a];
        const Vec3 pi = wrapped[a] - n.shift;
        const Vec3 gi = given[a];
        for (std::size_t b = same ? a + 1 : s1; b < e1; ++b) {
          // Hot loop: 3 subtractions, a squared norm and a compare per candidate.
          const Vec3 d = pi - wrapped[b];
          const double r2 = d.squaredNorm();
          if (r2 > testSquared) continue;
          // Below half the box no component is long enough for minimumImage to change d.
          const double r = !fromTest          ? box.minimumImage(gi - given[b]).norm()
                           : r2 < halfSquared ? std::sqrt(r2)
                                              : box.minimumImage(d).norm();
          if (r > cutoff) continue;
          const std::size_t j = original[b];
          visit(std::min(i, j), std::max(i, j), r);
        }
      }
    }
  }
}

}  // namespace grainbridge::extract::geometry
