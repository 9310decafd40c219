#pragma once
// Collisional dissipation rate of a frame, J = (1/V) sum over particle pairs of
// -F_diss . (u_i - u_j) at the contact point: the power the dissipative force parts the frame
// carries (dashpots, and the tangential part the engine books as dissipative) take out of the
// relative motion. u_i = v_i + omega_i x (c - r_i) includes rotation; for a pair across a
// Lees-Edwards boundary j is the image at r_i - branch, moving with the streaming velocity of
// its shift, gammadot (r_j' - r_j)_y in x. It is the DEM counterpart of Eq. 5.7.
//
// Wall contacts are left out: the frame stores their total forces only, not the elastic and
// dissipative split. In a Lees-Edwards box (no walls) this is the whole dissipation; in steady
// simple shear it equals the shear work -sigma_xy gammadot (the DEM engine checks that balance
// to 2 %). Coulomb sliding loses energy also when the tangential spring is reset to the cap;
// that loss is not in the dissipative part, nor is the tangential spring energy a contact
// carries off when it opens, so with friction J from this function is a lower bound (9-56 %
// of the shear work at friction 0.5 in the shear sweep) and the extract stage takes the shear
// work as J under Lees-Edwards shear.
#include <cstddef>

#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::coarse {

// Throws grainbridge::Error for a frame whose contact list names a particle it does not hold
// or for a non-positive volume.
double dissipationRate(const core::data::ParticleFrame& frame, double volume);
// -F_diss . (u_i - u_j) of contact k alone [W]; i and j are its particles' frame indices.
double contactDissipationPower(const core::data::ParticleFrame& frame, std::size_t k, std::size_t i, std::size_t j);

}  // namespace grainbridge::extract::coarse
