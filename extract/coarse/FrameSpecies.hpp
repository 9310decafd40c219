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

inline FrameSpecies frameSpecies(const core::data::ParticleFrame& frame) {
  FrameSpecies s;
  s.ids = frame.species;
  std::sort(s.ids.begin(), s.ids.end());
  s.ids.erase(std::unique(s.ids.begin(), s.ids.end()), s.ids.end());
  s.slot.resize(frame.size());
  for (std::size_t i = 0; i < frame.size(); ++i) {
    s.slot[i] =
        static_cast<std::size_t>(std::lower_bound(s.ids.begin(), s.ids.end(), frame.species[i]) - s.ids.begin());
  }
  return s;
}

}  // namespace grainbridge::extract::coarse
