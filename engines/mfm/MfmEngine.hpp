#pragma once
// The multi-fluid engine as the time-loop driver sees it (core::engine::SteppedEngine). The
// solver's own step adapts (TimeStepControl), so the driver's step is a fixed interval of
// simulated time, `interval`: advance() takes as many solver steps as it needs to reach the next
// multiple of it. Frames and series rows fall on those instants, and a checkpoint written
// between two of them holds the adaptive step's state too, so a resumed run takes exactly the
// steps the uninterrupted one takes.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "core/data/FieldFrame.hpp"
#include "core/engine/SteppedEngine.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "engines/mfm/MultiFluidEngine.hpp"
#include "engines/mfm/MultiFluidSetup.hpp"

namespace grainbridge::mfm {

// 2: each phase's granular temperature too. The flow state is fluid/FlowStateIo's layout at the
// root, the step, adaptive step and statistics attributes beside it.
// 3: the boundary mass account (initial_mass, boundary_mass: phase x patch x {in, out}).
inline constexpr int kCheckpointFormatVersion = 3;

class MfmEngine final : public core::engine::SteppedEngine {
 public:
  // `initial` fills the fresh engine's state (regions, initial pressure).
  MfmEngine(const MultiFluidSetup& setup, const std::function<void(MultiFluidEngine&)>& initial,
            const std::filesystem::path& outputDir, core::io::ArtifactStamp stamp);
  // Continues from a state written by saveState() with the same fingerprint; throws
  // grainbridge::Error naming the file otherwise.
  static std::unique_ptr<MfmEngine> restore(const MultiFluidSetup& setup, const std::filesystem::path& stateFile,
                                            const std::string& fingerprint, const std::filesystem::path& outputDir,
                                            core::io::ArtifactStamp stamp);

  void advance(bool observed) override;
  [[nodiscard]] double time() const override { return engine_->time(); }
  [[nodiscard]] std::int64_t step() const override { return step_; }
  void saveState(const std::filesystem::path& file, const std::string& fingerprint) const override;
  void writeFrames() override;
  bool writeFramesIfUsable() override;
  [[nodiscard]] std::string workItem() const override { return "cell"; }
  [[nodiscard]] std::int64_t workItems() const override;
  // The solver's adaptive steps (retried ones not counted), not the driver's output intervals.
  [[nodiscard]] std::int64_t workSteps() const override { return engine_->statistics().steps; }
  [[nodiscard]] std::string workStep() const override { return "solver step"; }
  [[nodiscard]] std::string throughputNote() const override;

  [[nodiscard]] const MultiFluidEngine& engine() const { return *engine_; }
  [[nodiscard]] MultiFluidEngine& mutableEngine() { return *engine_; }
  // The current state as a field frame: cell-centred velocities, the granular temperature of
  // each solids phase (the granular-energy equation's, or the algebraic one).
  [[nodiscard]] core::data::FieldFrame frame() const;

 private:
  MfmEngine(const MultiFluidSetup& setup, const std::filesystem::path& outputDir, core::io::ArtifactStamp stamp);

  std::unique_ptr<MultiFluidEngine> engine_;
  double interval_;
  std::int64_t step_ = 0;
  core::io::FieldFrameWriter writer_;
};

}  // namespace grainbridge::mfm
