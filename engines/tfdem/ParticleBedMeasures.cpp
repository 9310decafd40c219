#include "engines/tfdem/ParticleBedMeasures.hpp"

#include <unordered_map>

#include "engines/tfdem/ParticleDeposit.hpp"

namespace grainbridge::tfdem {

double meanParticleHeight(std::span<const Vec3> positions, const fluid::VerticalAxis& up, double bottom) {
  if (positions.empty()) return 0.0;
  double sum = 0.0;
  for (const Vec3& x : positions) sum += up.up * (x[up.axis] - bottom);
  return sum / static_cast<double>(positions.size());
}

double meanParticleHeight(const dem::Particles& particles, const fluid::VerticalAxis& up, double bottom) {
  return meanParticleHeight(std::span<const Vec3>(particles.x.data(), particles.nOwned), up, bottom);
}

double buoyantWeightPerArea(const dem::Particles& particles, double gasDensity, double gravity, double bottomArea) {
  double weight = 0.0;
  for (std::size_t i = 0; i < particles.nOwned; ++i) {
    weight += (particles.mass[i] - gasDensity * particleVolume(particles.radius[i])) * gravity;
  }
  return bottomArea > 0.0 ? weight / bottomArea : 0.0;
}

ContactNumbers contactNumbers(const core::data::ContactList& contacts, std::int64_t particles) {
  ContactNumbers out;
  if (particles <= 0) return out;
  out.coordination = 2.0 * static_cast<double>(contacts.size()) / static_cast<double>(particles);
  std::unordered_map<std::int64_t, int> neighbours;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    ++neighbours[contacts.i[k]];
    ++neighbours[contacts.j[k]];
  }
  std::int64_t touching = 0, multi = 0;
  for (const auto& [id, n] : neighbours) {
    ++touching;  // every listed particle has N_c >= 1
    if (n >= 2) ++multi;
  }
  out.multiContactRatio = touching > 0 ? static_cast<double>(multi) / static_cast<double>(touching) : 0.0;
  return out;
}

}  // namespace grainbridge::tfdem
