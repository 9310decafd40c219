#include "extract/structure/NetworkExtent.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::structure {

namespace {

// Breadth-first walk from member 0: u_b = u_a - branch for an edge (a, b) met from a, and
// u_a = u_b + branch when met from b. Sets wrapsAround when a non-tree edge disagrees with the
// walk by more than round-off (its cycle wraps through the box).
std::vector<Vec3> unwrapCentres(std::size_t memberCount, const std::vector<ExtentEdge>& edges, bool& wrapsAround) {
  // CSR adjacency: offsets per member, then the incident edge indices.
  std::vector<std::size_t> offset(memberCount + 1, 0);
  for (const ExtentEdge& e : edges) {
    if (e.a >= memberCount || e.b >= memberCount) {
      throw Error("network edge (" + std::to_string(e.a) + ", " + std::to_string(e.b) + ") names a member beyond the " +
                  std::to_string(memberCount) + " members of the network");
    }
    ++offset[e.a + 1];
    ++offset[e.b + 1];
  }
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  std::vector<std::size_t> incident(offset.back());
  std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
  double longestBranch = 0.0;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    incident[fill[edges[k].a]++] = k;
    incident[fill[edges[k].b]++] = k;
    longestBranch = std::max(longestBranch, edges[k].branch.norm());
  }

  std::vector<Vec3> unwrapped(memberCount, Vec3::Zero());
  std::vector<char> reached(memberCount, 0);
  std::vector<char> treeEdge(edges.size(), 0);
  std::vector<std::size_t> queue{0};
  reached[0] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t v = queue[head];
    for (std::size_t p = offset[v]; p < offset[v + 1]; ++p) {
      const ExtentEdge& e = edges[incident[p]];
      const std::size_t other = e.a == v ? e.b : e.a;
      if (reached[other]) continue;
      unwrapped[other] = e.a == v ? Vec3(unwrapped[v] - e.branch) : Vec3(unwrapped[v] + e.branch);
      reached[other] = 1;
      treeEdge[incident[p]] = 1;
      queue.push_back(other);
    }
  }
  if (queue.size() != memberCount) {
    throw Error("network edges reach only " + std::to_string(queue.size()) + " of its " + std::to_string(memberCount) +
                " members; a network must be connected");
  }

  // Round-off along a walk of thousands of branches is ~1e-12 of a branch; a wrap is a box length.
  const double tolerance = 1e-6 * longestBranch;
  wrapsAround = false;
  for (std::size_t k = 0; k < edges.size() && !wrapsAround; ++k) {
    if (treeEdge[k]) continue;
    const ExtentEdge& e = edges[k];
    wrapsAround = (unwrapped[e.a] - unwrapped[e.b] - e.branch).norm() > tolerance;
  }
  return unwrapped;
}

// Exact largest pairwise distance with pruning: with centres sorted by distance r from their
// centroid, |u_a - u_b| <= r_a + r_b, so once r_a + r_b cannot beat the best pair found the rest
// is skipped. A double sweep (farthest from any point, then farthest from that) seeds the best
// value near the answer, leaving a thin outer shell to compare pairwise. Worst case O(n^2).
double largestPairDistance(const std::vector<Vec3>& u) {
  const std::size_t n = u.size();
  if (n < 2) return 0.0;
  const auto farthestFrom = [&](const Vec3& x) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < n; ++k) {
      if ((u[k] - x).squaredNorm() > (u[best] - x).squaredNorm()) best = k;
    }
    return best;
  };
  const std::size_t p = farthestFrom(u[0]);
  const std::size_t q = farthestFrom(u[p]);
  double best = (u[p] - u[q]).norm();

  Vec3 centroid = Vec3::Zero();
  for (const Vec3& x : u) centroid += x;
  centroid /= static_cast<double>(n);
  std::vector<double> radius(n);
  for (std::size_t k = 0; k < n; ++k) radius[k] = (u[k] - centroid).norm();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return radius[a] > radius[b]; });

  for (std::size_t s = 0; s < n; ++s) {
    const double ra = radius[order[s]];
    if (ra + radius[order[0]] <= best) break;
    for (std::size_t t = s + 1; t < n; ++t) {
      if (ra + radius[order[t]] <= best) break;
      best = std::max(best, (u[order[s]] - u[order[t]]).norm());
    }
  }
  return best;
}

}  // namespace

NetworkExtent measureNetworkExtent(std::size_t memberCount, const std::vector<ExtentEdge>& edges, const Vec3& gravity) {
  NetworkExtent extent;
  if (memberCount == 0) return extent;
  if (!gravity.allFinite()) throw Error("the gravity direction for network extents is not finite");
  const std::vector<Vec3> u = unwrapCentres(memberCount, edges, extent.wrapsAroundBox);

  Vec3 lo = u[0], hi = u[0];
  for (const Vec3& x : u) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  extent.axisExtent = hi - lo;

  if (gravity.norm() > 0.0) {
    const Vec3 down = gravity.normalized();
    double lowest = u[0].dot(down), highest = lowest;
    for (const Vec3& x : u) {
      lowest = std::min(lowest, x.dot(down));
      highest = std::max(highest, x.dot(down));
    }
    extent.gravityExtent = highest - lowest;
  }
  extent.largestCentreDistance = largestPairDistance(u);
  return extent;
}

}  // namespace grainbridge::extract::structure
