// engine lammps in a build without liblammps: `grainbridge check` refuses it first
// (ParticleEngineKind::unavailable); these only guard a caller that skipped the check.
#include "core/Error.hpp"
#include "engines/lammps/LammpsEngineFactory.hpp"
#include "engines/lammps/LammpsInput.hpp"

namespace grainbridge::lammps {

namespace {

[[noreturn]] void noLammps() {
  throw Error("this build has no engine lammps (" + lammpsBuildNote() + "): install liblammps-dev and rebuild");
}

}  // namespace

std::unique_ptr<dem::ParticleEngine> startLammpsEngine(const dem::ParticleEngineStart& /*start*/,
                                                       dem::Particles /*particles*/) {
  noLammps();
}

std::unique_ptr<dem::ParticleEngine> restoreLammpsEngine(const dem::ParticleEngineStart& /*start*/,
                                                         const std::filesystem::path& /*state*/,
                                                         const std::string& /*fingerprint*/) {
  noLammps();
}

}  // namespace grainbridge::lammps
