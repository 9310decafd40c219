#pragma once
// Eq. 2.3 split by species, for the closures of a mixture (issue 60): each species' partial
// stress and granular temperature, and each species pair's contact stress and dissipation.
//
// Kinetic part: sum over species s's particles of m C C / V, C = v - u(r) less the mixture's mean
// peculiar velocity (as core/data/WholeDomainStress), so the species' kinetic stresses add up to
// the mixture's and T_s = tr(K_s) / (3 M_s) is each species' temperature about the mixture's
// flow, as the mixture kinetic theories define it (Garzo and Dufty 1999, Phys. Fluids 11, 3498:
// T_i from the peculiar velocity V = v - U of the mixture).
//
// Contact part: a contact's branch r_i - r_j is cut at its contact point c, and particle i takes
// (r_i - c) F, particle j (c - r_j) F (F the force on i), the split of the partial contact stress
// of Tunuguntla, Thornton and Weinhart 2016 (Comp. Part. Mech. 3:349, "From discrete elements to
// continuum fields: extension to bidisperse systems"), MercuryDPM's; the two parts add up to the
// branch's r_ij F of Eq. 2.3. A wall contact goes to its particle whole. A pair's total, which
// needs no such split, is kept too: the contacts between species a and b, a <= b, their stress
// sum r_ij F / V and the power their dashpots take (DissipationRate.hpp), per unit volume.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::coarse {

struct SpeciesPartialStress {
  std::int32_t species = 0;
  std::size_t particles = 0;
  double solidFraction = 0.0;        // the species' solid volume over V
  double mass = 0.0;                 // [kg]
  Mat3 kinetic = Mat3::Zero();       // [Pa], positive in compression
  Mat3 contact = Mat3::Zero();       // [Pa], its share of every contact (see above)
  double granularTemperature = 0.0;  // tr(kinetic) V / (3 mass) [m^2/s^2]
  [[nodiscard]] Mat3 total() const { return kinetic + contact; }
};

struct SpeciesPairContacts {
  std::int32_t first = 0, second = 0;  // species ids, first <= second
  std::size_t contacts = 0;
  Mat3 stress = Mat3::Zero();  // sum of r_ij F / V over the pair's contacts [Pa]
  double dissipation = 0.0;    // the pair's dashpot power per unit volume [W/m^3]
};

struct SpeciesStresses {
  std::vector<SpeciesPartialStress> species;  // by species id, ascending
  std::vector<SpeciesPairContacts> pairs;     // every pair of the frame's species (a <= b), by (a, b)
};

// Over the sample volume V. Throws grainbridge::Error for a non-positive volume or a contact that
// names a particle the frame does not hold.
SpeciesStresses speciesStresses(const core::data::ParticleFrame& frame, double volume);

}  // namespace grainbridge::extract::coarse
