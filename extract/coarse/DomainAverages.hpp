#pragma once
// Whole-domain averages of one particle frame: Eq. 2.3 over the sample volume V (the box by
// default), solid fraction, granular temperature (Eq. 3.38) per species and in total, bulk
// coordination number (Fig. 7.5) and the multi-contact ratio (Fig. 7.11).
//
// The stress sums come from core/data/WholeDomainStress.hpp, the implementation the DEM engine's
// series uses too: C about the streaming profile u_x = gammadot (y - y_mid) under Lees-Edwards,
// less the mean of the peculiar velocities.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::coarse {

struct SpeciesDomainAverages {
  std::int32_t species = 0;
  std::size_t particles = 0;
  double solidFraction = 0.0;    // [-]
  double density = 0.0;          // partial bulk density [kg/m^3]
  Vec3 velocity = Vec3::Zero();  // mass-weighted mean [m/s]
  // Eq. 3.38, C about this species' mean peculiar velocity [m^2/s^2]
  double granularTemperature = 0.0;
};

struct DomainAverages {
  double volume = 0.0;  // sample volume V [m^3]
  std::size_t particles = 0, pairContacts = 0, wallContacts = 0;
  double solidFraction = 0.0, density = 0.0;
  Vec3 velocity = Vec3::Zero();
  double granularTemperature = 0.0;  // mixture, mass-weighted [m^2/s^2]
  // Eq. 2.3 over V, positive in compression [Pa]
  Mat3 kineticStress = Mat3::Zero(), contactStress = Mat3::Zero(), stress = Mat3::Zero();
  double pressure = 0.0, shearStress = 0.0, deviatoricStress = 0.0;  // see StressMeasures.hpp
  double coordinationNumber = 0.0;                                   // 2 * particle-particle contacts / particles
  double multiContactRatio = 0.0;  // particles with N_c >= 2 over those with N_c >= 1 (0 if none)
  std::vector<SpeciesDomainAverages> species;
};

// V = the domain box. Throws grainbridge::Error for an inconsistent frame or an empty box.
DomainAverages averageWholeDomain(const core::data::ParticleFrame& frame);
// An explicit sample volume (e.g. the region between walls); throws if it is not positive.
DomainAverages averageWholeDomain(const core::data::ParticleFrame& frame, double volume);

}  // namespace grainbridge::extract::coarse
