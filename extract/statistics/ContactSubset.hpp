#pragma once
// A frame restricted to some of its contacts: how the force statistics of a sub-ensemble (the
// contacts an MST pass found, Figs. 6.14-6.16) reuse the functions written for whole frames.
#include <cstddef>
#include <span>

#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::statistics {

// The frame with only the listed particle-particle contacts, in the order given; particles, wall
// contacts and everything else unchanged. Throws grainbridge::Error naming an index beyond the
// contact list.
core::data::ParticleFrame withContacts(const core::data::ParticleFrame& frame, std::span<const std::size_t> keep);

}  // namespace grainbridge::extract::statistics
