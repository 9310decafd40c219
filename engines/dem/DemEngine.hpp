#pragma once
// The DEM engine as the time-loop driver sees it (core::engine::SteppedEngine): a Simulation,
// the writer of its particle + contact frames, and its checkpoint files. Stages reach the
// Simulation itself for setup-time changes (preparation phases) and for series observers.
#include <filesystem>
#include <memory>
#include <optional>

#include "core/io/ParticleFrameWriter.hpp"
#include "engines/dem/ParticleEngine.hpp"
#include "engines/dem/Simulation.hpp"

namespace grainbridge::dem {

class DemEngine final : public ParticleEngine {
 public:
  // Frames go to `outputDir`/frames and `outputDir`/particles.xmf.
  DemEngine(SimulationSetup setup, Particles particles, const std::filesystem::path& outputDir,
            core::io::ArtifactStamp stamp);
  // Continues from a state written by saveState() with the same `fingerprint`; throws
  // grainbridge::Error naming the file otherwise.
  static std::unique_ptr<DemEngine> restore(SimulationSetup setup, const std::filesystem::path& stateFile,
                                            const std::string& fingerprint, const std::filesystem::path& outputDir,
                                            core::io::ArtifactStamp stamp);

  void advance(bool observed) override;
  [[nodiscard]] double time() const override { return sim_.time(); }
  [[nodiscard]] std::int64_t step() const override { return sim_.stepCount(); }
  void saveState(const std::filesystem::path& file, const std::string& fingerprint) const override;
  void writeFrames() override;
  bool writeFramesIfUsable() override;
  [[nodiscard]] std::string workItem() const override { return "particle"; }
  [[nodiscard]] std::int64_t workItems() const override { return static_cast<std::int64_t>(sim_.particles().nOwned); }
  [[nodiscard]] std::string throughputNote() const override;

  [[nodiscard]] const Simulation& simulation() const { return sim_; }
  // For changes between steps (hold particles, change a wall's vibration, restart the clock).
  Simulation& mutableSimulation() {
    frame_.reset();
    return sim_;
  }
  // The current state as a frame, with the contacts of the last observed step; built once per
  // step however many observers and writers read it.
  const core::data::ParticleFrame& frame() override;
  [[nodiscard]] Energies energies() override { return sim_.energies(); }
  [[nodiscard]] std::int64_t mobileCount() override { return sim_.mobileCount(); }
  [[nodiscard]] std::vector<Vec3> wallForces() override { return sim_.wallForces(); }
  [[nodiscard]] std::int64_t neighbourRebuilds() const override { return sim_.rebuilds(); }
  void setMaterials(core::data::Materials materials) override {
    materials_ = std::move(materials);
    if (frame_) frame_->materials = materials_;
  }

 private:
  DemEngine(SimulationSetup setup, EngineState state, const std::filesystem::path& outputDir,
            core::io::ArtifactStamp stamp);

  Simulation sim_;
  core::io::ParticleFrameWriter writer_;
  std::optional<core::data::ParticleFrame> frame_;
  core::data::Materials materials_;
};

}  // namespace grainbridge::dem
