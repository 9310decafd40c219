#pragma once
// The dem stage's run on LAMMPS (issue 32): LAMMPS's GRANULAR package through its C library
// interface, opened on the instance's communicator, with the input LammpsInput translates from
// the same setup grainbridge's engine runs. It writes grainbridge's particle + contact frames, so
// extract, tabulate and the reports read a LAMMPS run as they read ours.
//
// Steps are run lazily: advance() counts them and the pending ones are run as one `run N pre no
// post no` when the state is next looked at (an observed step, a checkpoint, a frame). `pre no`
// keeps the forces of the last step, so the split runs are one uninterrupted LAMMPS run (a run
// with setup would recompute them with full-step velocities and move the trajectory).
//
// Contacts come from compute pair/local at the observed step's end, evaluated at the step's
// half-step velocities as grainbridge's own frames record them (LammpsEngine::frame()).
#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>

#include <mpi.h>

#include "core/io/ParticleFrameWriter.hpp"
#include "engines/dem/ParticleEngine.hpp"
#include "engines/dem/Particles.hpp"
#include "engines/lammps/LammpsInput.hpp"

namespace grainbridge::lammps {

// The layout of saveState's checkpoint (core/io/CheckpointFile): LAMMPS's restart file as bytes,
// the last step's forces and torques, step, time and whether any atom is frozen.
inline constexpr int kCheckpointFormatVersion = 1;

class LammpsEngine final : public dem::ParticleEngine {
 public:
  // `comm`: the instance's communicator, or MPI_COMM_NULL for a serial run (LAMMPS then
  // initialises MPI for itself, on this process alone). `lastStep`: the run's last step, which
  // fix deform interpolates its tilt towards (LAMMPS's run start/stop).
  LammpsEngine(const dem::SimulationSetup& setup, const LammpsSpeciesRadii& radii, const dem::Particles& particles,
               std::int64_t lastStep, MPI_Comm comm, const std::filesystem::path& outputDir,
               core::io::ArtifactStamp stamp);
  // Continues from a state written by saveState() with the same `fingerprint`; throws
  // grainbridge::Error naming the file otherwise.
  static std::unique_ptr<LammpsEngine> restore(const dem::SimulationSetup& setup, const LammpsSpeciesRadii& radii,
                                               std::int64_t lastStep, const std::filesystem::path& stateFile,
                                               const std::string& fingerprint, MPI_Comm comm,
                                               const std::filesystem::path& outputDir, core::io::ArtifactStamp stamp);
  ~LammpsEngine() override;
  LammpsEngine(const LammpsEngine&) = delete;
  LammpsEngine& operator=(const LammpsEngine&) = delete;

  void advance(bool observed) override;
  [[nodiscard]] double time() const override { return time_; }
  [[nodiscard]] std::int64_t step() const override { return step_; }
  void saveState(const std::filesystem::path& file, const std::string& fingerprint) const override;
  void writeFrames() override;
  bool writeFramesIfUsable() override;
  [[nodiscard]] std::string workItem() const override { return "particle"; }
  [[nodiscard]] std::int64_t workItems() const override { return atoms_; }
  [[nodiscard]] std::string throughputNote() const override;

  // Collective: every rank of the instance calls it at the same step. The particles and contacts
  // are gathered on the first rank only; the others get a frame without particles (they write
  // and sample nothing).
  const core::data::ParticleFrame& frame() override;
  [[nodiscard]] dem::Energies energies() override;
  [[nodiscard]] std::int64_t mobileCount() override;
  [[nodiscard]] std::vector<Vec3> wallForces() override;
  [[nodiscard]] std::int64_t neighbourRebuilds() const override { return -1; }
  void setMaterials(core::data::Materials materials) override {
    materials_ = std::move(materials);
    if (frame_) frame_->materials = materials_;
  }

 private:
  LammpsEngine(const dem::SimulationSetup& setup, const LammpsSpeciesRadii& radii, bool frozenAtoms,
               std::int64_t lastStep, MPI_Comm comm, const std::filesystem::path& outputDir,
               core::io::ArtifactStamp stamp);
  // Never before the current step (a run asked to go past its last step goes on).
  [[nodiscard]] std::int64_t lastStep() const { return std::max(lastStep_, step_); }
  void open(MPI_Comm comm);
  void command(const std::string& line) const;
  // The walls' fixes (LammpsInput::walls), made while LAMMPS is at `step`.
  void makeWalls(std::int64_t step);
  // Runs the steps advance() has counted.
  void flush() const;
  // `steps` steps in one `pre no` run.
  void runSteps(std::int64_t steps) const;
  // Under Lees-Edwards shear: the number of further steps until the one at whose end fix deform
  // finds the tilt past half the box and flips it (the flip itself comes at the next step); the
  // lists are rebuilt on every step from one before that to one after (flush()).
  [[nodiscard]] std::int64_t stepsToFlip() const;
  // After a resumed run's setup: its forces are the checkpoint's (restoredForces_).
  void putBackForces() const;
  [[nodiscard]] bool leader() const;

  dem::SimulationSetup setup_;
  LammpsInput input_;
  bool frozenAtoms_ = false;  // some atoms are of a frozen type
  void* lmp_ = nullptr;
  MPI_Comm comm_ = MPI_COMM_NULL;  // the instance's, or MPI_COMM_NULL when serial
  mutable std::int64_t pending_ = 0;
  mutable bool setUp_ = false;  // LAMMPS has run its setup (the first run has `pre yes`)
  // A step has run since the setup: the forces held are a step's, evaluated at half-step
  // velocities (the setup's are at the state's own).
  mutable bool halfStep_ = false;
  mutable bool forcesPending_ = false;  // restoredForces_ still to be put back
  mutable std::int64_t setupStep_ = 0;  // the step of LAMMPS's last setup (fix deform's origin)
  std::int64_t lastStep_ = 0;           // the run's last step
  std::int64_t step_ = 0;
  double time_ = 0.0;
  mutable std::int64_t atoms_ = 0;
  std::optional<core::io::ParticleFrameWriter> writer_;  // on the instance's first rank only
  // The forces and torques (per atom id) of the last step before a checkpoint, put back after
  // the setup LAMMPS needs after write_restart or read_restart (which recomputes them at
  // full-step velocities), so that the run continues as it would have.
  mutable std::vector<double> restoredForces_;
  std::optional<core::data::ParticleFrame> frame_;
  std::vector<std::int32_t> frozen_;  // per frame particle: 1 when its type is a frozen one
  core::data::Materials materials_;
};

}  // namespace grainbridge::lammps
