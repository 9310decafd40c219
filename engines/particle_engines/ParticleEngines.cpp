#include "engines/particle_engines/ParticleEngines.hpp"

#include "core/Error.hpp"
#include "engines/dem/DemEngine.hpp"
#include "engines/lammps/LammpsEngineFactory.hpp"
#include "engines/lammps/LammpsInput.hpp"

namespace grainbridge::particle_engines {

namespace {

ParticleEngineKind grainbridgeEngine() {
  ParticleEngineKind k;
  k.name = "grainbridge";
  k.preparation = true;
  k.unavailable = [] { return std::string(); };
  k.problems = [](const dem::SimulationSetup&, const std::vector<double>&) {
    return std::vector<core::engine::SetupProblem>{};  // the setup's own rules are the engine's
  };
  k.fresh = [](const dem::ParticleEngineStart& start,
               dem::Particles particles) -> std::unique_ptr<dem::ParticleEngine> {
    return std::make_unique<dem::DemEngine>(start.setup, std::move(particles), start.outputDir, start.stamp);
  };
  k.restore = [](const dem::ParticleEngineStart& start, const std::filesystem::path& state,
                 const std::string& fingerprint) -> std::unique_ptr<dem::ParticleEngine> {
    return dem::DemEngine::restore(start.setup, state, fingerprint, start.outputDir, start.stamp);
  };
  return k;
}

ParticleEngineKind lammpsEngine() {
  ParticleEngineKind k;
  k.name = "lammps";
  k.severalRanks = true;
  k.unavailable = [] {
    if (lammps::lammpsAvailable()) return std::string();
    return "this build has no engine lammps (" + lammps::lammpsBuildNote() +
           "): install Debian's liblammps-dev and lammps (scripts/install-deps.sh) and rebuild grainbridge";
  };
  k.problems = [](const dem::SimulationSetup& setup, const std::vector<double>& radii) {
    return lammps::lammpsProblems(setup, lammps::LammpsSpeciesRadii{radii});
  };
  k.fresh = lammps::startLammpsEngine;
  k.restore = lammps::restoreLammpsEngine;
  return k;
}

}  // namespace

const std::vector<ParticleEngineKind>& particleEngines() {
  static const std::vector<ParticleEngineKind> kinds{grainbridgeEngine(), lammpsEngine()};
  return kinds;
}

std::vector<std::string> particleEngineNames() {
  std::vector<std::string> names;
  for (const auto& k : particleEngines()) names.push_back(k.name);
  return names;
}

const ParticleEngineKind& particleEngine(std::string_view name) {
  for (const auto& k : particleEngines()) {
    if (k.name == name) return k;
  }
  std::string known;
  for (const auto& k : particleEngines()) known += (known.empty() ? "" : ", ") + k.name;
  throw Error("no particle engine named \"" + std::string(name) + "\" (known: " + known + ")");
}

}  // namespace grainbridge::particle_engines
