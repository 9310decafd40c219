#pragma once
// All particle pairs whose minimum-image centre distance is at most a cutoff: the candidate edges
// of the multi-pass MST (Section 6.3.3). A cell list with cells no smaller than the cutoff, built
// on the frame's box (PeriodicBox: periodic and Lees-Edwards images included), so the cost is
// O(N * neighbours) instead of the O(N^2) of all pairs.
#include <cstdint>
#include <vector>

#include "core/Types.hpp"
#include "extract/structure/PeriodicBox.hpp"

namespace grainbridge::extract::structure {

struct CandidatePair {
  double length = 0.0;         // |minimumImage(r_a - r_b)|
  std::uint32_t a = 0, b = 0;  // indices into the positions passed in, a < b
};

// Every pair (a < b) of positions with minimum-image distance <= cutoff, exactly once, in no
// particular order. Distances come from PeriodicBox::minimumImage of the raw positions, never
// from the cell layout, so they do not depend on the cutoff. Throws grainbridge::Error for a
// negative or non-finite cutoff, a non-finite position, or more than 2^32 - 1 particles.
std::vector<CandidatePair> findCandidatePairs(const std::vector<Vec3>& positions, const PeriodicBox& box,
                                              double cutoff);

}  // namespace grainbridge::extract::structure
