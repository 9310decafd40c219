#pragma once
// The species present in a frame, sorted, and each particle's position in that list: per-species
// fields (solid fraction and granular temperature of each solids phase) are stored in this order.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::coarse {

struct FrameSpecies {
  std::vector<std::int32_t> ids;  // sorted, distinct
  std::vector<std::size_t> slot;  // per particle: index into ids
};

// Fills s, reusing its storage. Linear in the particles for the usual handful of species (runs
// of one species, as engines insert them, skip the search): sorting a copy of every particle's
// species was a visible part of coarse graining a large frame.
inline void frameSpecies(const core::data::ParticleFrame& frame, FrameSpecies& s) {
  s.ids.clear();
  const std::size_t n = frame.size();
  constexpr std::size_t manySpecies = 64;  // beyond this, inserting into a sorted list is slower
  for (std::size_t i = 0; i < n && s.ids.size() <= manySpecies; ++i) {
    if (i > 0 && frame.species[i] == frame.species[i - 1]) continue;
    const auto at = std::lower_bound(s.ids.begin(), s.ids.end(), frame.species[i]);
    if (at == s.ids.end() || *at != frame.species[i]) s.ids.insert(at, frame.species[i]);
  }
  if (s.ids.size() > manySpecies) {
    s.ids = frame.species;
    std::sort(s.ids.begin(), s.ids.end());
    s.ids.erase(std::unique(s.ids.begin(), s.ids.end()), s.ids.end());
  }
  s.slot.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.slot[i] =
        i > 0 && frame.species[i] == frame.species[i - 1]
            ? s.slot[i - 1]
            : static_cast<std::size_t>(std::lower_bound(s.ids.begin(), s.ids.end(), frame.species[i]) - s.ids.begin());
  }
}

inline FrameSpecies frameSpecies(const core::data::ParticleFrame& frame) {
  FrameSpecies s;
  frameSpecies(frame, s);
  return s;
}

}  // namespace grainbridge::extract::coarse
