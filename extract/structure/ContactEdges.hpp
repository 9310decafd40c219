#pragma once
// The particle-particle contact list of a frame as graph edges between particle ranks (ascending
// id order, see ParticleIdIndex), each with its signed normal force
//   F_n = forceNormal . branch / |branch|,
// branch = r_i - r_j and forceNormal the force on i from j (core/data/ContactList.hpp), so
// F_n > 0 is repulsion, the sign convention of core/data/WholeDomainStress.hpp (r_ij F_ij > 0 in
// compression). A linear or Hertz dashpot can make the total normal force attractive near the
// end of a contact; such a contact has F_n < 0 and is not part of a force network (Section
// 6.3.2: "each particle has a nonzero normal contact force"; VALIDATION.md: networks use F_n > 0).
// Wall contacts live in a separate list and are never edges: coordination counts particle-
// particle contacts only.
#include <cstddef>
#include <vector>

#include "core/data/ParticleFrame.hpp"
#include "extract/structure/ParticleIdIndex.hpp"

namespace grainbridge::extract::structure {

struct ContactEdge {
  std::size_t rankI = 0, rankJ = 0;  // ranks of the contact's i and j, in the list's order
  std::size_t contactIndex = 0;      // position in frame.contacts
  double normalForce = 0.0;          // signed F_n as above; > 0 repulsive

  [[nodiscard]] bool repulsive() const { return normalForce > 0.0; }
};

// Every entry of frame.contacts, in list order. Throws grainbridge::Error naming the contact for
// an id missing from the frame, a particle in contact with itself, a zero branch vector (F_n
// would have no direction) or a particle pair listed twice.
std::vector<ContactEdge> listContactEdges(const core::data::ParticleFrame& frame, const ParticleIdIndex& index);

}  // namespace grainbridge::extract::structure
