#pragma once
// TF-DEM (Section 7.2.3): DEM particles in the averaged gas. One advance() is one gas step of
// fluid_dt, which is `substeps` DEM steps of dt:
//   1. deposit the particles on the gas grid (ParticleDeposit: Eqs. 7.35-7.36);
//   2. one gas step at the fixed fluid_dt from the last deposit's fractions to this one's, so the
//      gas continuity sees d eps_g / dt of the particles (fluid::advance with the last level
//      given); a step that does not converge stops the run, naming the time, equation and cell;
//   3. the particles' forces from the converged gas (ParticleForces: -V_p grad P_g and the drag);
//   4. `substeps` DEM steps, the drag recorded at each (dem::FluidCoupling), and for the summed
//      gas reaction deposited per cell at that sub-step's positions and averaged over the
//      sub-steps: what the next gas step receives (Eq. 7.32).
// Frames: the particles (their external_force the drag alone, Fig. 7.7's f') into the output
// folder, the gas's field frames into its `gas` folder. One checkpoint file holds the DEM state,
// the flow state and the summed drag, so a resumed run continues bit for bit.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/engine/SteppedEngine.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "core/io/H5InputFile.hpp"
#include "core/io/ParticleFrameWriter.hpp"
#include "engines/closures/GasSolidsDrag.hpp"
#include "engines/dem/Simulation.hpp"
#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/SimpleStep.hpp"
#include "engines/tfdem/ParticleDeposit.hpp"
#include "engines/tfdem/ParticleForces.hpp"
#include "engines/tfdem/ParticleGasModel.hpp"
#include "engines/tfdem/TfdemSetup.hpp"

namespace grainbridge::tfdem {

class TfdemEngine final : public core::engine::SteppedEngine {
 public:
  // `initialGas` is the gas at rest or flowing before the first step (its fraction is replaced by
  // what the particles leave). Frames go to outputDir (particles) and outputDir/gas (the gas).
  TfdemEngine(TfdemSetup setup, dem::Particles particles, const fluid::FlowState& initialGas,
              const std::filesystem::path& outputDir, core::io::ArtifactStamp stamp);
  // Continues from a state written by saveState() with the same fingerprint; throws
  // grainbridge::Error naming the file otherwise.
  static std::unique_ptr<TfdemEngine> restore(TfdemSetup setup, const std::filesystem::path& stateFile,
                                              const std::string& fingerprint, const std::filesystem::path& outputDir,
                                              core::io::ArtifactStamp stamp);

  // Its fields point at its own grid: never copied or moved.
  TfdemEngine(const TfdemEngine&) = delete;
  TfdemEngine& operator=(const TfdemEngine&) = delete;

  void advance(bool observed) override;
  [[nodiscard]] double time() const override { return flow_.time; }
  [[nodiscard]] std::int64_t step() const override { return step_; }
  void saveState(const std::filesystem::path& file, const std::string& fingerprint) const override;
  void writeFrames() override;
  bool writeFramesIfUsable() override;
  [[nodiscard]] std::string workItem() const override { return "particle"; }
  [[nodiscard]] std::int64_t workItems() const override { return static_cast<std::int64_t>(sim_.particles().nOwned); }
  // Each gas step is `substeps` DEM steps of every particle.
  [[nodiscard]] std::int64_t workSteps() const override { return step_ * setup_.substeps; }
  [[nodiscard]] std::string workStep() const override { return "DEM step"; }
  [[nodiscard]] std::string throughputNote() const override;

  // A phase without the gas (settling the bed before the gas is turned on): advance() runs the
  // DEM sub-steps alone with no force from the gas, keeps the gas's clock and its particle
  // fractions with the particles (so the first gas step starts from where they are), and leaves
  // the gas's pressure and velocity as they are. Not part of the saved state: a stage sets it
  // when a phase starts or resumes.
  void setGasActive(bool active);
  [[nodiscard]] bool gasActive() const { return gasActive_; }
  // The run's clock, the particles' and the gas's, and the step count start at zero.
  void restartClock();
  // New gas patches from the next gas step on (an inflow ramp: a fluidization curve in one run).
  // Not part of the saved state: a caller that changes them sets them again on resuming.
  // Throws grainbridge::Error as the constructor does for patches the grid cannot take.
  void setPatches(std::vector<fluid::BoundaryPatch> patches);

  [[nodiscard]] const dem::Simulation& simulation() const { return sim_; }
  [[nodiscard]] const fluid::FlowState& flow() const { return flow_; }
  [[nodiscard]] const fluid::StaggeredGrid& grid() const { return grid_; }
  [[nodiscard]] const fluid::Boundaries& boundaries() const { return boundaries_; }
  [[nodiscard]] const TfdemSetup& setup() const { return setup_; }
  // The deposit of the last gas step (the particles as they were before its DEM sub-steps).
  [[nodiscard]] const ParticleDeposit& deposit() const { return deposit_; }
  // Momentum the particles received from the gas's drag over the last gas step, per padded cell
  // (each sub-step's drag at that sub-step's cells, times dt) [N s]; and what the gas received
  // from the particles over its last step [N s], from its exchange at the cell centres:
  // beta_c (v_s,c - v_g,c) V fluid_dt (cell_average) or its source times V fluid_dt (summed).
  [[nodiscard]] const std::vector<Vec3>& particleDragImpulse() const { return particleImpulse_; }
  [[nodiscard]] const std::vector<Vec3>& gasDragImpulse() const { return gasImpulse_; }
  // Outer iterations of the last gas step.
  [[nodiscard]] int gasIterations() const { return lastIterations_; }
  // The current state as the gas's field frame and the particles' frame.
  [[nodiscard]] core::data::FieldFrame gasFrame() const;
  const core::data::ParticleFrame& particleFrame();

 private:
  TfdemEngine(TfdemSetup setup, const core::io::H5InputFile& checkpoint, const std::filesystem::path& outputDir,
              core::io::ArtifactStamp stamp);
  // What both constructors do first: the coupling's settings, the drag's record, the deposit of
  // the particles as they are, no summed drag yet.
  void startCoupling();
  // What the gas's frames carry: gravity and their one particle phase.
  [[nodiscard]] core::data::Materials gasFrameMaterials() const;
  // The gas's particle phase and fraction from deposit_, ghosts included.
  void gasFollowsDeposit();

  TfdemSetup setup_;
  fluid::StaggeredGrid grid_;
  fluid::Boundaries boundaries_;
  dem::Simulation sim_;
  fluid::FlowState flow_;
  ParticleDeposit deposit_;
  std::vector<Vec3> summedDrag_;  // per padded cell, the particles' mean drag per volume [N/m^3]
  std::vector<Vec3> particleImpulse_, gasImpulse_;
  std::int64_t step_ = 0;
  int lastIterations_ = 0;
  std::int64_t gasSteps_ = 0, gasIterations_ = 0;  // since this engine was made: the log's mean
  bool gasActive_ = true;
  core::io::ParticleFrameWriter particleWriter_;
  core::io::FieldFrameWriter gasWriter_;
  std::optional<core::data::ParticleFrame> frame_;
};

}  // namespace grainbridge::tfdem
