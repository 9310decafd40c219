#include "engines/dem/DemEngine.hpp"

#include <sstream>

#include "engines/dem/Checkpoint.hpp"
#include "engines/dem/FrameOutput.hpp"

namespace grainbridge::dem {

DemEngine::DemEngine(SimulationSetup setup, Particles particles, const std::filesystem::path& outputDir,
                     core::io::ArtifactStamp stamp)
    : sim_(std::move(setup), std::move(particles)), writer_(outputDir, std::move(stamp)) {}

DemEngine::DemEngine(SimulationSetup setup, EngineState state, const std::filesystem::path& outputDir,
                     core::io::ArtifactStamp stamp)
    : sim_(std::move(setup), std::move(state)), writer_(outputDir, std::move(stamp)) {}

std::unique_ptr<DemEngine> DemEngine::restore(SimulationSetup setup, const std::filesystem::path& stateFile,
                                              const std::string& fingerprint, const std::filesystem::path& outputDir,
                                              core::io::ArtifactStamp stamp) {
  // Not make_unique: the state constructor is private, so a restored engine is always one read
  // through the fingerprint check.
  return std::unique_ptr<DemEngine>(
      new DemEngine(std::move(setup), readCheckpoint(stateFile, fingerprint), outputDir, std::move(stamp)));
}

void DemEngine::advance(bool observed) {
  frame_.reset();
  sim_.step(observed);
}

void DemEngine::saveState(const std::filesystem::path& file, const std::string& fingerprint) const {
  writeCheckpoint(file, sim_.captureState(), fingerprint);
}

const core::data::ParticleFrame& DemEngine::frame() {
  if (!frame_) frame_ = outputFrame(sim_, materials_);
  return *frame_;
}

void DemEngine::writeFrames() { writer_.write(frame()); }

bool DemEngine::writeFramesIfUsable() {
  if (!finiteParticles(sim_.particles())) return false;
  frame_.reset();
  writeFrames();
  return true;
}

std::string DemEngine::throughputNote() const {
  std::ostringstream note;
  note.setf(std::ios::fixed);
  note.precision(3);
  note << 2.0 * static_cast<double>(sim_.contactCount()) / static_cast<double>(sim_.particles().nOwned)
       << " contacts per particle (2 x particle pairs / N, walls not counted)";
  // As LAMMPS's "Neighbor list builds": how often the skin ran out, over the steps this engine has
  // taken (a preparation's included, a resumed run's earlier ones not; the first build counted).
  note << ", " << sim_.rebuilds() << " neighbour-list builds in " << sim_.stepsTaken() << " steps";
  if (sim_.stepsTaken() > 0) {
    note.precision(1);
    note << " (one per " << static_cast<double>(sim_.stepsTaken()) / static_cast<double>(sim_.rebuilds()) << ")";
  }
  return note.str();
}

}  // namespace grainbridge::dem
