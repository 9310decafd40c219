#pragma once
// Normal contact forces of one frame for the force statistics of Section 6.3.2. The signed
// normal force is F_n = F_normal . n with n = branch / |branch| (branch = r_i - r_j, force on i
// from j), so F_n > 0 is repulsive, the sign under which Eq. 2.3's r_ij F_ij is positive in
// compression (core/data/WholeDomainStress.hpp). Only F_n > 0 enters force PDFs and correlations:
// a dashpot can make the total normal force attractive (VALIDATION.md, force networks).
#include <cstddef>
#include <span>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::statistics {

struct RepulsiveForces {
  std::vector<double> normalForce;   // F_n > 0, in the frame's force unit (N in SI)
  std::vector<double> f;             // F_n / <F_n>, the normalised force of Eqs. 6.11-6.13
  std::vector<Vec3> contactPoint;    // positions for the correlation of Eq. 6.12
  std::vector<std::size_t> contact;  // index into frame.contacts
  double meanForce = 0.0;            // <F_n> over the repulsive contacts
  std::size_t contactsInFrame = 0;   // all particle-particle contacts, repulsive or not
};

// Particle-particle contacts only (wall contacts are not pairs of Eq. 6.12 and are left out of
// the PDF as in Fig. 6.12). Throws grainbridge::Error naming the step when the frame has no
// contact with F_n > 0, or a contact with a zero or non-finite branch vector.
RepulsiveForces repulsiveForces(const core::data::ParticleFrame& frame);

// f = F_n / <F_n> of every repulsive contact of every frame, each frame normalised by its own
// mean (as Fig. 6.12(a) does for its frame), pooled: the sample for a force PDF over frames.
std::vector<double> normalisedForces(std::span<const core::data::ParticleFrame> frames);

}  // namespace grainbridge::extract::statistics
