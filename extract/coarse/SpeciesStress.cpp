#include "extract/coarse/SpeciesStress.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "core/data/StreamingProfile.hpp"
#include "extract/coarse/DissipationRate.hpp"
#include "extract/coarse/FrameSpecies.hpp"
#include "extract/coarse/ParticleContacts.hpp"

namespace grainbridge::extract::coarse {

SpeciesStresses speciesStresses(const core::data::ParticleFrame& frame, double volume) {
  if (!(volume > 0.0) || !std::isfinite(volume)) {
    throw Error("species stresses: sample volume " + std::to_string(volume) + " must be positive");
  }
  const FrameSpecies species = frameSpecies(frame);
  const std::size_t n = frame.size(), kinds = species.ids.size();
  SpeciesStresses out;
  out.species.resize(kinds);
  for (std::size_t s = 0; s < kinds; ++s) out.species[s].species = species.ids[s];
  for (std::size_t a = 0; a < kinds; ++a) {
    for (std::size_t b = a; b < kinds; ++b) out.pairs.push_back({species.ids[a], species.ids[b]});
  }
  // The pair (a, b), a <= b, of slots: row a of the upper triangle.
  const auto pairOf = [kinds](std::size_t a, std::size_t b) -> std::size_t {
    if (a > b) std::swap(a, b);
    return a * kinds - a * (a - 1) / 2 + (b - a);
  };

  // C about the mixture's mean peculiar velocity (two passes, as WholeDomainStress).
  std::vector<Vec3> peculiar(n);
  Vec3 momentum = Vec3::Zero();
  double totalMass = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    peculiar[i] = frame.velocity[i] - core::data::streamingVelocity(frame.domain, frame.position[i]);
    momentum += frame.mass[i] * peculiar[i];
    totalMass += frame.mass[i];
  }
  const Vec3 mean = totalMass > 0.0 ? Vec3(momentum / totalMass) : Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    SpeciesPartialStress& s = out.species[species.slot[i]];
    const Vec3 c = peculiar[i] - mean;
    ++s.particles;
    s.mass += frame.mass[i];
    s.solidFraction += 4.0 / 3.0 * M_PI * std::pow(frame.radius[i], 3);
    s.kinetic += frame.mass[i] * c * c.transpose();
  }

  const ParticleIndex index(frame);
  const auto& pc = frame.contacts;
  for (std::size_t k = 0; k < pc.size(); ++k) {
    const std::size_t i = index.at(pc.i[k], "species stresses: contact", k);
    const std::size_t j = index.at(pc.j[k], "species stresses: contact", k);
    const Vec3 force = pc.forceNormal[k] + pc.forceTangential[k];
    const Vec3 toContact = frame.position[i] - pc.contactPoint[k];  // r_i - c; the rest of the branch is j's
    out.species[species.slot[i]].contact += toContact * force.transpose();
    out.species[species.slot[j]].contact += (pc.branch[k] - toContact) * force.transpose();
    SpeciesPairContacts& pair = out.pairs[pairOf(species.slot[i], species.slot[j])];
    ++pair.contacts;
    pair.stress += pc.branch[k] * force.transpose();
    pair.dissipation += contactDissipationPower(frame, k, i, j);
  }
  const auto& wc = frame.wallContacts;
  for (std::size_t k = 0; k < wc.size(); ++k) {
    const std::size_t i = index.at(wc.particle[k], "species stresses: wall contact", k);
    out.species[species.slot[i]].contact +=
        (frame.position[i] - wc.point[k]) * (wc.forceNormal[k] + wc.forceTangential[k]).transpose();
  }

  for (SpeciesPartialStress& s : out.species) {
    if (s.mass > 0.0) s.granularTemperature = s.kinetic.trace() / (3.0 * s.mass);
    s.solidFraction /= volume;
    s.kinetic /= volume;
    s.contact /= volume;
  }
  for (SpeciesPairContacts& p : out.pairs) {
    p.stress /= volume;
    p.dissipation /= volume;
  }
  return out;
}

}  // namespace grainbridge::extract::coarse
