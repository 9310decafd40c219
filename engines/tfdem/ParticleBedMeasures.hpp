#pragma once
// Measures of a particle bed that the TF-DEM reports read (Section 7.3.2): the mean particle
// height, the arithmetic mean of every particle's height along gravity (line 1982's definition,
// Fig. 7.9), and the contact numbers of Figs. 7.5, 7.6 and 7.11: the bulk coordination number
// 2 N_contacts / N and the multi-contact ratio, particles with N_c >= 2 over those with N_c >= 1
// (N_c a particle's contacting neighbours; walls are not neighbours).
#include <cstdint>
#include <span>

#include "core/data/ContactList.hpp"
#include "engines/dem/Particles.hpp"
#include "engines/fluid/BedMeasures.hpp"

namespace grainbridge::tfdem {

// The particles' mean height above the bottom, the domain's side at coordinate `bottom` along
// `up`'s axis [m]; 0 without particles. Of positions (a frame's), or of a run's owned particles.
[[nodiscard]] double meanParticleHeight(std::span<const Vec3> positions, const fluid::VerticalAxis& up, double bottom);
[[nodiscard]] double meanParticleHeight(const dem::Particles& particles, const fluid::VerticalAxis& up, double bottom);

// The particles' buoyant weight per unit area of the bottom [Pa]: sum_p m_p (1 - rho_g / rho_p) |g|
// over `bottomArea` (what a fluidized bed's pressure drop carries; a 2D bed's area is its width
// times its one-particle depth). Frozen particles count too: the gas sees them as well.
[[nodiscard]] double buoyantWeightPerArea(const dem::Particles& particles, double gasDensity, double gravity,
                                          double bottomArea);

struct ContactNumbers {
  double coordination = 0.0;       // 2 contacts / particles
  double multiContactRatio = 0.0;  // N_c >= 2 over N_c >= 1; 0 when no particle touches another
};

// From the particle-particle contacts of a frame, over `particles` particles.
[[nodiscard]] ContactNumbers contactNumbers(const core::data::ContactList& contacts, std::int64_t particles);

}  // namespace grainbridge::tfdem
