#include "engines/tfdem/TfdemEngine.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"
#include "core/io/CheckpointFile.hpp"
#include "engines/dem/Checkpoint.hpp"
#include "engines/dem/FrameOutput.hpp"
#include "engines/fluid/FieldSampling.hpp"
#include "engines/fluid/FlowFrame.hpp"
#include "engines/fluid/FlowStateIo.hpp"

namespace grainbridge::tfdem {

namespace fs = std::filesystem;

namespace {

// 1: the DEM state in /particles, the flow in /gas, the summed drag and the step at the root.
// 2: the particles' state holds the time of their last list build (dem's format 4)
constexpr int kCheckpointFormatVersion = 2;

// The setup with the DEM told that the gas's forces apply.
TfdemSetup fluidCoupled(TfdemSetup setup) {
  setup.particles.fluidCoupled = true;
  return setup;
}

std::string describe(const fluid::StepResult& r) {
  std::ostringstream s;
  if (!r.failure.empty()) {
    s << r.failure;
  } else {
    s << "the " << r.equation << " residual " << r.residual << " after " << r.iterations << " iterations";
  }
  s << ", cell (" << r.cell[0] << ", " << r.cell[1] << ", " << r.cell[2] << ")";
  return s.str();
}

}  // namespace

TfdemEngine::TfdemEngine(TfdemSetup setup, dem::Particles particles, const fluid::FlowState& initialGas,
                         const fs::path& outputDir, core::io::ArtifactStamp stamp)
    : setup_(fluidCoupled(std::move(setup))),
      grid_(setup_.grid),
      boundaries_(grid_, setup_.boundaries, 2),
      sim_(setup_.particles, std::move(particles)),
      flow_(grid_, 2),
      deposit_(grid_),
      particleWriter_(outputDir, stamp),
      gasWriter_(outputDir / "gas", stamp) {
  startCoupling();
  if (initialGas.phases.size() != 2 || initialGas.grid().paddedCount() != grid_.paddedCount())
    throw Error("tfdem: the initial gas state is not of the gas grid with two phases");
  // Values, not fields: the engine's fields live on its own grid.
  flow_.time = initialGas.time;
  flow_.pressure.values() = initialGas.pressure.values();
  for (int a = 0; a < 3; ++a) {
    const auto axis = static_cast<std::size_t>(a);
    flow_.phases[0].velocity[axis].values() = initialGas.phases[0].velocity[axis].values();
  }
  gasFollowsDeposit();
}

TfdemEngine::TfdemEngine(TfdemSetup setup, const core::io::H5InputFile& checkpoint, const fs::path& outputDir,
                         core::io::ArtifactStamp stamp)
    : setup_(fluidCoupled(std::move(setup))),
      grid_(setup_.grid),
      boundaries_(grid_, setup_.boundaries, 2),
      sim_(setup_.particles, dem::readEngineState(checkpoint, "/particles")),
      flow_(grid_, 2),
      deposit_(grid_),
      particleWriter_(outputDir, stamp),
      gasWriter_(outputDir / "gas", stamp) {
  startCoupling();
  fluid::readFlowState(checkpoint, "/gas", flow_);
  summedDrag_ = checkpoint.readVec3s("/summed_drag", {grid_.paddedCount()});
  step_ = checkpoint.readIntAttribute("/", "step");
}

void TfdemEngine::startCoupling() {
  setup_.forces.gas = setup_.gas;
  sim_.bodyForces().setRecording<dem::FluidCoupling>(true);  // the drag alone: frames, Eq. 7.32
  deposit_ = depositParticles(grid_, sim_.particles(), setup_.deposition);
  summedDrag_.assign(grid_.paddedCount(), Vec3::Zero());
  particleImpulse_.assign(grid_.paddedCount(), Vec3::Zero());
  gasImpulse_.assign(grid_.paddedCount(), Vec3::Zero());
}

void TfdemEngine::gasFollowsDeposit() {
  setParticlePhase(deposit_, flow_.phases[1]);
  for (std::size_t c = 0; c < grid_.paddedCount(); ++c) {
    if (grid_.interior(c)) flow_.phases[0].fraction[c] = 1.0 - flow_.phases[1].fraction[c];
  }
  boundaries_.apply(flow_);
}

void TfdemEngine::setPatches(std::vector<fluid::BoundaryPatch> patches) {
  boundaries_ = fluid::Boundaries(grid_, patches, 2);
  setup_.boundaries = std::move(patches);
  boundaries_.apply(flow_);
}

void TfdemEngine::setGasActive(bool active) {
  gasActive_ = active;
  if (active) return;
  dem::Particles& p = sim_.mutableParticles();
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    p.couplingPressure[i].setZero();
    p.couplingA[i].setZero();
    p.couplingB[i] = 0.0;
    p.couplingU[i].setZero();
  }
  std::fill(summedDrag_.begin(), summedDrag_.end(), Vec3::Zero());
}

void TfdemEngine::restartClock() {
  sim_.restartClock();
  flow_.time = 0.0;
  step_ = 0;
}

void TfdemEngine::advance(bool observed) {
  frame_.reset();
  const double fluidDt = setup_.fluidDt();
  if (!gasActive_) {
    for (int s = 0; s < setup_.substeps; ++s) sim_.step(observed && s + 1 == setup_.substeps);
    deposit_ = depositParticles(grid_, sim_.particles(), setup_.deposition);
    gasFollowsDeposit();
    flow_.time += fluidDt;
    std::fill(particleImpulse_.begin(), particleImpulse_.end(), Vec3::Zero());
    std::fill(gasImpulse_.begin(), gasImpulse_.end(), Vec3::Zero());
    ++step_;
    return;
  }
  // 1-2. The particles as they are now, and the gas step from the last deposit to this one.
  ParticleDeposit next = depositParticles(grid_, sim_.particles(), setup_.deposition);
  fluid::FlowState state = flow_;
  setParticlePhase(next, state.phases[1]);
  const ParticleGasModel model(setup_.gas, setup_.drag, setup_.gasReaction, next, &summedDrag_);
  const fluid::StepResult r = fluid::advance(state, flow_, fluidDt, model, boundaries_, setup_.solver);
  if (!r.converged) {
    std::ostringstream s;
    s << "tfdem: the gas step of " << fluidDt << " s from t = " << flow_.time << " s did not converge: " << describe(r)
      << " (a smaller fluid_dt, or a coarser grid, may help)";
    throw Error(s.str());
  }
  flow_ = std::move(state);
  deposit_ = std::move(next);
  lastIterations_ = r.iterations;
  ++gasSteps_;
  gasIterations_ += r.iterations;

  // What the gas received over its step, at the cell centres, and Eq. 7.34's beta per cell.
  const ParticleGasModel converged(setup_.gas, setup_.drag, setup_.gasReaction, deposit_, &summedDrag_);
  const bool summed = setup_.gasReaction == GasReaction::Summed;
  const bool cellAverage = setup_.forces.transfer == DragTransfer::CellAverage;
  const double V = grid_.cellVolume();
  const std::vector<double> beta =
      !summed || cellAverage ? converged.cellBetas(flow_) : std::vector<double>(grid_.paddedCount(), 0.0);
  const std::vector<Vec3> cellDrag = cellDragPerSolidsVolume(flow_, deposit_, beta);
  for (std::size_t c = 0; c < grid_.paddedCount(); ++c) {
    // The gas's exchange is the particles' drag with the sign turned: beta (v_s - v_g) V, or the
    // summed source.
    gasImpulse_[c] = summed ? Vec3(-summedDrag_[c] * V * fluidDt)
                            : Vec3(-cellDrag[c] * deposit_.fraction[c] * V * fluidDt);
  }

  // 3. The particles' forces from the converged gas.
  setParticleForces(sim_.mutableParticles(), flow_, deposit_, cellDrag, setup_.drag, setup_.forces);

  // 4. The DEM sub-steps. What the particles received is deposited per cell: with cell_average
  // each particle's drag is the sum of its cells' parts V_p w_ic D_c, held over the sub-steps, so
  // each part goes to its own cell (exactly the cell's exchange); otherwise each sub-step's drag
  // goes to the cells at that sub-step's positions (Eq. 7.32). Frozen particles receive none.
  std::fill(particleImpulse_.begin(), particleImpulse_.end(), Vec3::Zero());
  const double dt = setup_.particles.dt;
  const dem::Particles& p = sim_.particles();
  if (cellAverage) {
    for (std::size_t i = 0; i < p.nOwned; ++i) {
      if (p.isFrozen(i)) continue;
      const double vp = particleVolume(p.radius[i]);
      for (std::size_t k = deposit_.offset[i]; k < deposit_.offset[i + 1]; ++k) {
        const auto& [c, w] = deposit_.shares[k];
        particleImpulse_[c] += w * vp * cellDrag[c] * fluidDt;
      }
    }
  }
  const std::optional<GasGridCells> cells = cellAverage ? std::nullopt : std::optional<GasGridCells>(grid_);
  core::grid::CellShares one;
  for (int s = 0; s < setup_.substeps; ++s) {
    const bool sampled = observed && s + 1 == setup_.substeps;
    // The drag each particle received is needed at every sub-step for Eq. 7.32's sum; with
    // cell_average only for the frame of an observed step (recording it at every sub-step cost
    // the jet 1 % of its instructions).
    sim_.bodyForces().setRecording<dem::FluidCoupling>(!cellAverage || sampled);
    sim_.step(sampled);
    if (cellAverage) continue;
    const std::vector<Vec3>& drag = sim_.bodyForces().applied<dem::FluidCoupling>();
    for (std::size_t i = 0; i < p.nOwned; ++i) {
      if (drag[i].isZero(0.0)) continue;
      cells->shares(p.x[i], p.radius[i], setup_.deposition, one);
      for (const auto& share : one) particleImpulse_[share.cell] += share.fraction * drag[i] * dt;
    }
  }
  // Eq. 7.32's summed reaction for the next gas step: the sub-steps' mean drag per volume.
  for (std::size_t c = 0; c < grid_.paddedCount(); ++c) summedDrag_[c] = particleImpulse_[c] / (V * fluidDt);
  ++step_;
}

void TfdemEngine::saveState(const fs::path& path, const std::string& fingerprint) const {
  core::io::writeCheckpointFile(path, {kCheckpointFormatVersion, fingerprint}, [this](core::io::H5OutputFile& f) {
    dem::writeEngineState(f, sim_.captureState(), "/particles");
    fluid::writeFlowState(f, "/gas", flow_);
    f.writeDataset("/summed_drag", summedDrag_);
    f.writeAttribute("/", "step", static_cast<std::int64_t>(step_));
  });
}

std::unique_ptr<TfdemEngine> TfdemEngine::restore(TfdemSetup setup, const fs::path& stateFile,
                                                  const std::string& fingerprint, const fs::path& outputDir,
                                                  core::io::ArtifactStamp stamp) {
  const auto f = core::io::openCheckpointFile(stateFile, {kCheckpointFormatVersion, fingerprint});
  return std::unique_ptr<TfdemEngine>(new TfdemEngine(std::move(setup), f, outputDir, std::move(stamp)));
}

core::data::Materials TfdemEngine::gasFrameMaterials() const {
  // The gas sees one particle phase. Of one species it is that species; of several, "particles"
  // with their Sauter mean diameter sum d^3 / sum d^2 (the diameter that keeps the phase's volume
  // and surface, which the drag of a mixed cell goes by) and their volume-weighted density.
  core::data::Materials m;
  m.gravity = setup_.materials.gravity;
  const auto& species = setup_.materials.species;
  if (species.size() == 1) m.species = species;
  if (species.size() <= 1) return m;
  const dem::Particles& p = sim_.particles();
  double d3 = 0.0, d2 = 0.0, massSum = 0.0;
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    const double d = 2.0 * p.radius[i];
    d3 += d * d * d;
    d2 += d * d;
    massSum += p.mass[i];
  }
  if (d2 > 0.0) m.species.push_back({"particles", d3 / d2, massSum / (M_PI / 6.0 * d3)});
  return m;
}

core::data::FieldFrame TfdemEngine::gasFrame() const {
  auto materials = gasFrameMaterials();
  const std::string particles = materials.species.empty() ? "particles" : materials.species.front().name;
  // The particles' theta stays zero: their own fluctuation is the DEM's, not a field here.
  auto f = fluid::flowFrame(grid_, flow_, step_, {particles},
                            [&](std::size_t c, std::size_t out, std::vector<core::data::SolidsPhaseFields>& phases) {
                              phases[0].ep_s[out] = deposit_.fraction[c];
                              phases[0].u_s[out] = deposit_.velocity[c];
                            });
  f.materials = std::move(materials);
  return f;
}

const core::data::ParticleFrame& TfdemEngine::particleFrame() {
  if (!frame_) {
    frame_ = dem::outputFrame(sim_, setup_.materials);
    const auto& drag = sim_.bodyForces().applied<dem::FluidCoupling>();
    if (drag.size() == sim_.particles().nOwned) frame_->externalForce = drag;
  }
  return *frame_;
}

void TfdemEngine::writeFrames() {
  particleWriter_.write(particleFrame());
  gasWriter_.write(gasFrame());
}

bool TfdemEngine::writeFramesIfUsable() {
  if (!dem::finiteParticles(sim_.particles())) return false;
  for (std::size_t c = 0; c < grid_.paddedCount(); ++c) {
    if (grid_.interior(c) && !std::isfinite(flow_.pressure[c])) return false;
  }
  frame_.reset();
  writeFrames();
  return true;
}

std::string TfdemEngine::throughputNote() const {
  std::ostringstream note;
  note.setf(std::ios::fixed);
  note.precision(2);
  note << static_cast<double>(gasIterations_) / static_cast<double>(std::max<std::int64_t>(gasSteps_, 1))
       << " gas iterations per gas step, "
       << 2.0 * static_cast<double>(sim_.contactCount()) / static_cast<double>(std::max<std::size_t>(sim_.particles().nOwned, 1))
       << " contacts per particle";
  return note.str();
}

}  // namespace grainbridge::tfdem
