#pragma once
// Particles on a face-centred cubic lattice filling a box: the start of dense states (solid
// fraction 0.4-0.6, the dense end of the shear-closure sweep) that random sequential insertion
// cannot reach (it jams near 0.38). The lattice has at least `count` sites; the vacancies are
// chosen at random, and under shear the crystal melts within a few strain units.
#include <random>
#include <vector>

#include "core/Types.hpp"

namespace grainbridge::dem {

// `count` lattice sites in [lo, hi), in random order. Throws grainbridge::Error when spheres
// of diameter `diameter` do not fit (nearest-neighbour distance below it), naming the densest
// solid fraction a lattice of this many spheres allows.
std::vector<Vec3> fccLatticeSites(const Vec3& lo, const Vec3& hi, std::size_t count, double diameter,
                                  std::mt19937_64& rng);

}  // namespace grainbridge::dem
