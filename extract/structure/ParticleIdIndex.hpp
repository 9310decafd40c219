#pragma once
// Global particle id -> position in the frame's arrays. Contacts name particles by global id
// (core/data/ContactList.hpp), so every structure analysis starts here. Particles are also
// ranked by ascending id: the MST works on ranks so that comparing two ranks compares the ids,
// which is the tie-break rule of VALIDATION.md ("ties break on (w, min id, max id)").
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace grainbridge::extract::structure {

class ParticleIdIndex {
 public:
  // Throws grainbridge::Error naming a repeated id.
  explicit ParticleIdIndex(const std::vector<std::int64_t>& ids);

  [[nodiscard]] std::size_t size() const { return sortedIds_.size(); }
  // Position of id in ascending id order, or nothing if the frame has no such particle.
  [[nodiscard]] std::optional<std::size_t> rankOf(std::int64_t id) const;
  [[nodiscard]] std::int64_t idAtRank(std::size_t rank) const { return sortedIds_[rank]; }
  [[nodiscard]] std::size_t frameIndexAtRank(std::size_t rank) const { return frameIndexByRank_[rank]; }
  [[nodiscard]] std::size_t rankOfFrameIndex(std::size_t frameIndex) const { return rankByFrameIndex_[frameIndex]; }
  // Like rankOf, but a missing id is an error naming `what` refers to it (e.g. "contact 12").
  [[nodiscard]] std::size_t requireRank(std::int64_t id, const char* what, std::size_t whichEntry) const;

 private:
  std::vector<std::int64_t> sortedIds_;
  std::vector<std::size_t> frameIndexByRank_, rankByFrameIndex_;
};

}  // namespace grainbridge::extract::structure
