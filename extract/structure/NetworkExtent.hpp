#pragma once
// Geometric size of a connected set of contacting particles (a force network, Section 6.3.2, or a
// tree of contacting particles, Section 6.3.3, whose "maximum distance between two particles"
// is the 52.2 d0 length scale of the reference).
//
// Definition. Particle centres are unwrapped by walking branch vectors (r_a - r_b, minimum image)
// outward from vertex 0 along a breadth-first spanning tree of the network, never by reading the
// stored (wrapped) positions, so a network that crosses a periodic or Lees-Edwards boundary is
// measured as one piece. On the unwrapped centres:
//   axisExtent[k]          = max - min of coordinate k (centres, radii not added);
//   gravityExtent          = max - min of the projection on the unit gravity direction;
//   largestCentreDistance  = max |u_a - u_b| over all member pairs.
// All three are translation invariant, so where the walk starts does not matter. A network whose
// cycles add up to a whole box vector (it percolates through a periodic boundary and touches its
// own image) has no single unwrapping: it is flagged and measured on the spanning-tree unwrapping.
#include <cstddef>
#include <vector>

#include "core/Types.hpp"

namespace grainbridge::extract::structure {

struct NetworkExtent {
  Vec3 axisExtent = Vec3::Zero();
  double gravityExtent = 0.0;  // 0 when no gravity direction is given
  double largestCentreDistance = 0.0;
  bool wrapsAroundBox = false;
};

struct ExtentEdge {
  std::size_t a = 0, b = 0;    // member indices, 0..memberCount-1
  Vec3 branch = Vec3::Zero();  // r_a - r_b under the minimum image
};

// Members 0..memberCount-1 joined by edges that must connect them all. gravity may be zero (no
// gravity extent) or any nonzero vector (only its direction is used). Throws grainbridge::Error if
// the edges leave a member unreachable or name a member out of range.
NetworkExtent measureNetworkExtent(std::size_t memberCount, const std::vector<ExtentEdge>& edges, const Vec3& gravity);

}  // namespace grainbridge::extract::structure
