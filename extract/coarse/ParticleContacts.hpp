#pragma once
// Per-particle contact data of one frame: the number of particle-particle contacts N_c (the
// coordination of Fig. 6.10 and Section 7.4, walls excluded as VALIDATION.md asks) and the total
// contact force on each particle, walls included (f_ci of Fig. 7.7: the force the drag competes
// with). Also the id -> index map every contact lookup needs.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::coarse {

// Index of each global id in the frame's arrays. Every contact is looked up (twice per contact
// per frame), so the map is a plain table indexed by id - smallest id when the ids are dense, as
// the engines number them; otherwise a sorted list searched by bisection.
class ParticleIndex {
 public:
  static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();

  ParticleIndex() = default;
  // Throws grainbridge::Error for a repeated id (the first repeat in frame order).
  explicit ParticleIndex(const core::data::ParticleFrame& frame) { assign(frame); }
  // Indexes another frame, reusing the storage (frame after frame: no fresh pages to fault in).
  void assign(const core::data::ParticleFrame& frame);

  // The frame index of id, or npos if the frame has no such particle.
  [[nodiscard]] std::size_t find(std::int64_t id) const {
    if (dense_) {
      // Unsigned wrap-around sends ids below the smallest past the end as well.
      const auto slot = static_cast<std::uint64_t>(id) - static_cast<std::uint64_t>(smallest_);
      return slot < table_.size() ? table_[static_cast<std::size_t>(slot)] : npos;
    }
    return findSorted(id);
  }
  // Like find, but a missing id is an error naming the entry that refers to it, as
  // "<list> <entry> refers to particle id <id>, which is not in the frame".
  [[nodiscard]] std::size_t at(std::int64_t id, const char* list, std::size_t entry) const {
    const std::size_t i = find(id);
    if (i == npos) throwMissing(id, list, entry);
    return i;
  }

 private:
  [[nodiscard]] std::size_t findSorted(std::int64_t id) const;
  [[noreturn]] static void throwMissing(std::int64_t id, const char* list, std::size_t entry);

  bool dense_ = false;
  std::int64_t smallest_ = 0;
  std::vector<std::size_t> table_;                            // dense: index by id - smallest
  std::vector<std::pair<std::int64_t, std::size_t>> sorted_;  // sparse: (id, index) by id
};

struct ParticleContacts {
  std::vector<int> count;        // particle-particle contacts of each particle, N_c
  std::vector<Vec3> totalForce;  // sum of contact forces on each particle (walls included) [N]
  std::size_t pairContacts = 0;  // particle-particle contacts in the frame
  // Frame index of particles i and j of each contact, and of the particle of each wall contact:
  // engines store particles in spatial order but number them at random, so looking ids up is a
  // cache miss each; one tight pass here overlaps them, and later passes read these in order.
  std::vector<std::size_t> first, second, wallParticle;
};

// Throws grainbridge::Error naming a contact whose particle id is not in the frame.
ParticleContacts particleContacts(const core::data::ParticleFrame& frame, const ParticleIndex& index);
// The same into out, reusing its storage (frame after frame: no fresh pages to fault in).
void particleContacts(const core::data::ParticleFrame& frame, const ParticleIndex& index, ParticleContacts& out);

}  // namespace grainbridge::extract::coarse
