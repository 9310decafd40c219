#include "engines/dem/FrameOutput.hpp"

namespace grainbridge::dem {

core::data::ParticleFrame outputFrame(Simulation& sim, const core::data::Materials& materials) {
  sim.refreshContacts();
  auto frame = sim.frame();
  frame.materials = materials;
  return frame;
}

bool finiteParticles(const Particles& p) {
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    if (!p.x[i].allFinite() || !p.v[i].allFinite()) return false;
  }
  return true;
}

}  // namespace grainbridge::dem
