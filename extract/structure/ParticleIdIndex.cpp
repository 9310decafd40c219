#include "extract/structure/ParticleIdIndex.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::structure {

ParticleIdIndex::ParticleIdIndex(const std::vector<std::int64_t>& ids)
    : frameIndexByRank_(ids.size()), rankByFrameIndex_(ids.size()) {
  std::iota(frameIndexByRank_.begin(), frameIndexByRank_.end(), std::size_t{0});
  std::sort(frameIndexByRank_.begin(), frameIndexByRank_.end(),
            [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
  sortedIds_.reserve(ids.size());
  for (std::size_t rank = 0; rank < ids.size(); ++rank) {
    const std::size_t k = frameIndexByRank_[rank];
    if (rank > 0 && ids[k] == sortedIds_.back()) {
      throw Error("particle id " + std::to_string(ids[k]) +
                  " appears more than once in the frame; ids must be unique global ids");
    }
    sortedIds_.push_back(ids[k]);
    rankByFrameIndex_[k] = rank;
  }
}

std::optional<std::size_t> ParticleIdIndex::rankOf(std::int64_t id) const {
  const auto it = std::lower_bound(sortedIds_.begin(), sortedIds_.end(), id);
  if (it == sortedIds_.end() || *it != id) return std::nullopt;
  return static_cast<std::size_t>(it - sortedIds_.begin());
}

std::size_t ParticleIdIndex::requireRank(std::int64_t id, const char* what, std::size_t whichEntry) const {
  const auto rank = rankOf(id);
  if (!rank) {
    throw Error(std::string(what) + " " + std::to_string(whichEntry) + " refers to particle id " + std::to_string(id) +
                ", which is not in the frame");
  }
  return *rank;
}

}  // namespace grainbridge::extract::structure
