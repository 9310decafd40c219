#pragma once
// The particle engines the dem stage runs on, by the name its `engine` key takes: grainbridge's
// own (engines/dem) and LAMMPS's GRANULAR package through liblammps (engines/lammps). The stage
// reads only this list, so a third engine is one entry here and its own folder; an engine this
// build lacks stays listed and says why (`grainbridge check` gives the same refusals with or
// without it).
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/engine/SetupProblem.hpp"
#include "engines/dem/ParticleEngine.hpp"
#include "engines/dem/ParticleEngineStart.hpp"
#include "engines/dem/Particles.hpp"

namespace grainbridge::particle_engines {

struct ParticleEngineKind {
  std::string name;           // the dem stage's `engine` value
  bool severalRanks = false;  // an instance may run on several ranks
  bool preparation = false;   // runs the two-step preparation (held species, shaken container)
  // Why this build has no such engine, with what to install; "" when it has it.
  std::function<std::string()> unavailable;
  // Every reason `setup` cannot run on this engine as it would on grainbridge's, at the pointer of
  // the dem stage's key (relative to /params); empty when it can.
  std::function<std::vector<core::engine::SetupProblem>(const dem::SimulationSetup& setup,
                                                        const std::vector<double>& speciesRadii)>
      problems;
  // A fresh run from `particles`.
  std::function<std::unique_ptr<dem::ParticleEngine>(const dem::ParticleEngineStart& start, dem::Particles particles)>
      fresh;
  // The run continued from a state the engine saved with the same fingerprint (the stage key).
  std::function<std::unique_ptr<dem::ParticleEngine>(
      const dem::ParticleEngineStart& start, const std::filesystem::path& state, const std::string& fingerprint)>
      restore;
};

// Every engine, grainbridge's first (the default).
const std::vector<ParticleEngineKind>& particleEngines();
std::vector<std::string> particleEngineNames();
// The engine of that name; throws grainbridge::Error naming the known ones otherwise.
const ParticleEngineKind& particleEngine(std::string_view name);

}  // namespace grainbridge::particle_engines
