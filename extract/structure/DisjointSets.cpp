#include "extract/structure/DisjointSets.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace grainbridge::extract::structure {

DisjointSets::DisjointSets(std::size_t count) : parent_(count), size_(count) { reset(); }

std::size_t DisjointSets::find(std::size_t v) {
  while (parent_[v] != v) {
    parent_[v] = parent_[parent_[v]];
    v = parent_[v];
  }
  return v;
}

bool DisjointSets::unite(std::size_t a, std::size_t b) {
  a = find(a);
  b = find(b);
  if (a == b) return false;
  if (size_[a] < size_[b]) std::swap(a, b);
  parent_[b] = a;
  size_[a] += size_[b];
  return true;
}

void DisjointSets::reset() {
  std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  std::fill(size_.begin(), size_.end(), std::size_t{1});
}

}  // namespace grainbridge::extract::structure
