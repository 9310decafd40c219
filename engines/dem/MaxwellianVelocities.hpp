#pragma once
// Maxwellian velocity fluctuations for an initial state: each component drawn from a normal
// distribution, then the mean removed and the spread rescaled so the sample has exactly zero
// momentum (about the streaming profile the caller adds) and exactly the granular temperature
// T = <C^2>/3 asked (Eq. 3.38). The one implementation the particle_gas and dem stages share.
#include <cstddef>
#include <random>
#include <vector>

#include "core/Types.hpp"

namespace grainbridge::dem {

// n velocities of equal-mass particles (3 n normal draws from rng whatever T); T = 0 or n < 2
// gives zeros (a single particle cannot carry a temperature at zero momentum).
std::vector<Vec3> maxwellianVelocities(std::size_t n, double temperature, std::mt19937_64& rng);

}  // namespace grainbridge::dem
