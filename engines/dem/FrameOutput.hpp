#pragma once
// What a particle engine (dem, the particles of TF-DEM) writes as a particle frame and when its
// state is worth writing, written once so the engines' frames agree.
#include "core/data/Materials.hpp"
#include "core/data/ParticleFrame.hpp"
#include "engines/dem/Particles.hpp"
#include "engines/dem/Simulation.hpp"

namespace grainbridge::dem {

// The frame of the present state stamped with `materials`. The contacts are refreshed first: the
// run's first frame after a preparation, a settling phase or a restart has no recorded step.
[[nodiscard]] core::data::ParticleFrame outputFrame(Simulation& sim, const core::data::Materials& materials);

// Whether every owned particle's position and velocity is finite. A particle that left the domain
// leaves a usable state; a non-finite one does not.
[[nodiscard]] bool finiteParticles(const Particles& p);

}  // namespace grainbridge::dem
