#pragma once
// Per-particle contact data of one frame: the number of particle-particle contacts N_c (the
// coordination of Fig. 6.10 and Section 7.4, walls excluded as VALIDATION.md asks) and the total
// contact force on each particle, walls included (f_ci of Fig. 7.7: the force the drag competes
// with). Also the id -> index map every contact lookup needs.
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::coarse {

// Index of each global id in the frame's arrays. Throws grainbridge::Error for a repeated id.
std::unordered_map<std::int64_t, std::size_t> indexById(const core::data::ParticleFrame& frame);

struct ParticleContacts {
  std::vector<int> count;        // particle-particle contacts of each particle, N_c
  std::vector<Vec3> totalForce;  // sum of contact forces on each particle (walls included) [N]
  std::size_t pairContacts = 0;  // particle-particle contacts in the frame
};

// Throws grainbridge::Error naming a contact whose particle id is not in the frame.
ParticleContacts particleContacts(const core::data::ParticleFrame& frame,
                                  const std::unordered_map<std::int64_t, std::size_t>& index);

}  // namespace grainbridge::extract::coarse
