#pragma once
// engine lammps as the particle-engine list (engines/particle_engines) starts it. Defined in
// LammpsEngine.cpp where this build has liblammps, in LammpsEngineOff.cpp (which throws, naming
// why) where it has not: the choice is CMake's, so no code outside engines/lammps asks.
#include <filesystem>
#include <memory>
#include <string>

#include "engines/dem/ParticleEngine.hpp"
#include "engines/dem/ParticleEngineStart.hpp"
#include "engines/dem/Particles.hpp"

namespace grainbridge::lammps {

std::unique_ptr<dem::ParticleEngine> startLammpsEngine(const dem::ParticleEngineStart& start, dem::Particles particles);
std::unique_ptr<dem::ParticleEngine> restoreLammpsEngine(const dem::ParticleEngineStart& start,
                                                         const std::filesystem::path& state,
                                                         const std::string& fingerprint);

}  // namespace grainbridge::lammps
