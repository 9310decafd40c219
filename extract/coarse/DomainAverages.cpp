#include "extract/coarse/DomainAverages.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "core/data/StreamingProfile.hpp"
#include "core/data/WholeDomainStress.hpp"
#include "extract/coarse/FrameSpecies.hpp"
#include "extract/coarse/ParticleContacts.hpp"
#include "extract/coarse/StressMeasures.hpp"

namespace grainbridge::extract::coarse {

DomainAverages averageWholeDomain(const core::data::ParticleFrame& frame) {
  return averageWholeDomain(frame, (frame.domain.hi - frame.domain.lo).prod());
}

DomainAverages averageWholeDomain(const core::data::ParticleFrame& frame, double volume) {
  if (!(volume > 0.0) || !std::isfinite(volume)) {
    throw Error("whole-domain averages: sample volume " + std::to_string(volume) + " must be positive");
  }
  frame.validate();
  const ParticleIndex index(frame);
  const ParticleContacts contacts = particleContacts(frame, index);
  const FrameSpecies species = frameSpecies(frame);
  const std::size_t n = frame.size();
  const std::size_t nSpecies = species.ids.size();

  DomainAverages out;
  out.volume = volume;
  out.particles = n;
  out.pairContacts = frame.contacts.size();
  out.wallContacts = frame.wallContacts.size();
  out.species.resize(nSpecies);

  std::vector<double> mass(nSpecies, 0.0), solidVolume(nSpecies, 0.0);
  std::vector<Vec3> momentum(nSpecies, Vec3::Zero()), peculiarMomentum(nSpecies, Vec3::Zero());
  std::vector<Vec3> peculiar(n);
  double totalMass = 0.0;
  Vec3 totalMomentum = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = species.slot[i];
    const double m = frame.mass[i];
    const double r = frame.radius[i];
    peculiar[i] = frame.velocity[i] - streamingVelocity(frame.domain, frame.position[i]);
    ++out.species[k].particles;
    mass[k] += m;
    solidVolume[k] += 4.0 / 3.0 * M_PI * r * r * r;
    momentum[k] += m * frame.velocity[i];
    peculiarMomentum[k] += m * peculiar[i];
    totalMass += m;
    totalMomentum += m * frame.velocity[i];
  }

  // Eq. 2.3 (core's one implementation) and the species temperatures of Eq. 3.38, each species'
  // C about its own mean peculiar velocity.
  const auto sums = core::data::wholeDomainStressSums(frame);
  out.kineticStress = sums.kinetic;
  out.contactStress = sums.contact;
  std::vector<double> c2(nSpecies, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = species.slot[i];
    if (mass[k] > 0.0) c2[k] += frame.mass[i] * (peculiar[i] - peculiarMomentum[k] / mass[k]).squaredNorm();
  }
  if (totalMass > 0.0) out.granularTemperature = out.kineticStress.trace() / (3.0 * totalMass);
  out.kineticStress /= volume;
  out.contactStress /= volume;
  out.stress = out.kineticStress + out.contactStress;
  out.pressure = pressure(out.stress);
  out.shearStress = shearStress(out.stress);
  out.deviatoricStress = deviatoricNorm(out.stress);

  double solid = 0.0;
  for (std::size_t k = 0; k < nSpecies; ++k) {
    SpeciesDomainAverages& s = out.species[k];
    s.species = species.ids[k];
    s.solidFraction = solidVolume[k] / volume;
    s.density = mass[k] / volume;
    if (mass[k] > 0.0) {
      s.velocity = momentum[k] / mass[k];
      s.granularTemperature = c2[k] / (3.0 * mass[k]);
    }
    solid += solidVolume[k];
  }
  out.solidFraction = solid / volume;
  out.density = totalMass / volume;
  if (totalMass > 0.0) out.velocity = totalMomentum / totalMass;

  std::size_t inContact = 0, multi = 0;
  for (int count : contacts.count) {
    if (count >= 1) ++inContact;
    if (count >= 2) ++multi;
  }
  if (n > 0) out.coordinationNumber = 2.0 * static_cast<double>(contacts.pairContacts) / static_cast<double>(n);
  if (inContact > 0) out.multiContactRatio = static_cast<double>(multi) / static_cast<double>(inContact);
  return out;
}

}  // namespace grainbridge::extract::coarse
