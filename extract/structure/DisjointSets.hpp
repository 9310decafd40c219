#pragma once
// Union-find over vertices 0..count-1, the workhorse of every component count in this folder
// (force networks, Kruskal's spanning forests, trees of contacting particles). Union by size
// with path halving: near-constant amortised cost, so a pass of Kruskal stays O(E log E) with
// the sort dominating.
#include <cstddef>
#include <vector>

namespace grainbridge::extract::structure {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t count);

  // Representative of v's set; halves the path on the way up.
  [[nodiscard]] std::size_t find(std::size_t v);
  // Joins the sets of a and b; false if they already were one set (the edge would close a cycle).
  bool unite(std::size_t a, std::size_t b);
  // Number of vertices in the set whose representative is root.
  [[nodiscard]] std::size_t sizeOfSet(std::size_t root) const { return size_[root]; }
  [[nodiscard]] std::size_t vertexCount() const { return parent_.size(); }
  // Back to singletons, keeping the allocation (one call per MST pass).
  void reset();

 private:
  std::vector<std::size_t> parent_, size_;
};

}  // namespace grainbridge::extract::structure
