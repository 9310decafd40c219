#pragma once
// How crystalline a frame is (issue 61): monodisperse frictionless spheres sheared near jamming
// can order into sliding layers, and such a box's stresses are not those of the random packing a
// closure table means. Two measures, both from the bond-orientational order of Steinhardt, Nelson
// and Ronchetti (Phys. Rev. B 28, 784, 1983) over each particle's neighbours within `cutoff` of
// its centre (by default 1.3 mean diameters: the first shell, short of an fcc lattice's second at
// 1.41 d):
//   - q6 per particle, sqrt(4 pi / 13 sum_m |q6m(i)|^2), q6m(i) = <Y6m(r_ij)> over its bonds,
//     averaged over the particles with at least one neighbour (about 0.57 in an fcc lattice, 0.48
//     in hcp; lower and broad in a random packing);
//   - the share of crystalline particles by the solid-bond criterion of Auer and Frenkel (Adv.
//     Polym. Sci. 173, 149, 2005) with pyscal's documented parameters (find_solids: bonds 6,
//     threshold 0.5): a bond i-j is solid when the normalised s_ij = Re sum_m q6m(i) q6m(j)^* /
//     (|q6(i)| |q6(j)|) >= 0.5, and a particle with at least 6 solid bonds is crystalline (1 in a
//     perfect fcc lattice; in the closure loop's sheared frictionless boxes 0.004-0.07 at solid
//     fraction 0.4-0.55, 0.09-0.13 in the random dense states at 0.57-0.62, 0.88 in the box that
//     ordered at 0.68).
#include <span>

#include "core/Types.hpp"
#include "core/data/Domain.hpp"

namespace grainbridge::extract::structure {

struct BondOrder {
  double meanQ6 = 0.0;            // over particles with a neighbour (0 if none has one)
  double crystallineShare = 0.0;  // of all particles
};

// Neighbours under the domain's periodic and Lees-Edwards images (geometry::PeriodicBox). Throws
// grainbridge::Error for a non-positive cutoff.
[[nodiscard]] BondOrder bondOrder(const core::data::Domain& domain, std::span<const Vec3> positions, double cutoff);

}  // namespace grainbridge::extract::structure
