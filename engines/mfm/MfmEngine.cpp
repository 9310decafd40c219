#include "engines/mfm/MfmEngine.hpp"

#include <cmath>
#include <sstream>

#include "core/io/CheckpointFile.hpp"
#include "engines/fluid/FieldSampling.hpp"
#include "engines/fluid/FlowFrame.hpp"
#include "engines/fluid/FlowStateIo.hpp"

namespace grainbridge::mfm {

namespace fs = std::filesystem;

MfmEngine::MfmEngine(const MultiFluidSetup& setup, const fs::path& outputDir, core::io::ArtifactStamp stamp)
    : engine_(
          std::make_unique<MultiFluidEngine>(setup.geometry, setup.patches, setup.model, setup.settings, setup.limits)),
      interval_(setup.interval),
      writer_(outputDir, std::move(stamp)) {}

MfmEngine::MfmEngine(const MultiFluidSetup& setup, const std::function<void(MultiFluidEngine&)>& initial,
                     const fs::path& outputDir, core::io::ArtifactStamp stamp)
    : MfmEngine(setup, outputDir, std::move(stamp)) {
  initial(*engine_);
  engine_->boundaries().apply(engine_->state());
  engine_->startMassAccount();
}

void MfmEngine::advance(bool /*observed*/) {
  // The target from the step count, not by adding intervals: no drift over many steps.
  engine_->advanceTo(static_cast<double>(step_ + 1) * interval_);
  ++step_;
}

std::int64_t MfmEngine::workItems() const {
  const auto& g = engine_->grid().geometry();
  return static_cast<std::int64_t>(g.cells[0]) * g.cells[1] * g.cells[2];
}

std::string MfmEngine::throughputNote() const {
  const auto& s = engine_->statistics();
  std::ostringstream out;
  out.precision(3);
  // The driver's line already counts the solver steps (workSteps).
  out << (s.steps > 0 ? static_cast<double>(s.iterations) / s.steps : 0.0) << " iterations per step, " << s.retries
      << " retried (" << s.retriedIterations << " iterations), last dt " << s.lastDt << " s";
  return out.str();
}

core::data::FieldFrame MfmEngine::frame() const {
  const auto& st = engine_->state();
  const auto& solids = engine_->model().params().solids;
  std::vector<std::string> names;
  for (const auto& s : solids) names.push_back(s.name);
  auto f = fluid::flowFrame(engine_->grid(), st, step_, names,
                            [&](std::size_t c, std::size_t out, std::vector<core::data::SolidsPhaseFields>& phases) {
                              for (std::size_t m = 1; m < st.phases.size(); ++m) {
                                auto& phase = phases[m - 1];
                                phase.ep_s[out] = st.phases[m].fraction[c];
                                phase.u_s[out] = fluid::cellVelocity(st.phases[m], c);
                                phase.theta[out] = engine_->model().granularTemperature(st, m, c);
                              }
                            });
  // The materials the fields are of, so readers need no stage params (DESIGN.md, field frames).
  f.materials.gravity = engine_->settings().gravity;
  for (const auto& s : solids) f.materials.species.push_back({s.name, s.diameter, s.density});
  return f;
}

void MfmEngine::writeFrames() { writer_.write(frame()); }

bool MfmEngine::writeFramesIfUsable() {
  const auto f = frame();
  for (double v : f.p_g) {
    if (!std::isfinite(v)) return false;
  }
  writer_.write(f);
  return true;
}

void MfmEngine::saveState(const fs::path& path, const std::string& fingerprint) const {
  core::io::writeCheckpointFile(path, {kCheckpointFormatVersion, fingerprint}, [this](core::io::H5OutputFile& f) {
    // The flow state at the root, where format 2 keeps it; beside it what is mfm's own: the
    // driver's step, the adaptive step and the statistics.
    fluid::writeFlowState(f, "/", engine_->state());
    const auto& stats = engine_->statistics();
    f.writeAttribute("/", "step", static_cast<std::int64_t>(step_));
    f.writeAttribute("/", "dt", engine_->timeStep().current());
    f.writeAttribute("/", "solver_steps", static_cast<std::int64_t>(stats.steps));
    f.writeAttribute("/", "retries", static_cast<std::int64_t>(stats.retries));
    f.writeAttribute("/", "iterations", static_cast<std::int64_t>(stats.iterations));
    f.writeAttribute("/", "retried_iterations", static_cast<std::int64_t>(stats.retriedIterations));
    f.writeAttribute("/", "last_dt", stats.lastDt);
    f.writeAttribute("/", "table_cell_steps", static_cast<std::int64_t>(stats.tableCellSteps));
    f.writeAttribute("/", "covered_cell_steps", static_cast<std::int64_t>(stats.coveredCellSteps));
    f.writeAttribute("/", "table_solids_steps", stats.tableSolidsSteps);
    f.writeAttribute("/", "covered_solids_steps", stats.coveredSolidsSteps);
    f.writeDataset("/initial_mass", stats.initialMass);
    std::vector<double> crossed;
    for (const auto& phase : stats.boundaryMass) {
      for (const fluid::PatchFlow& patch : phase) {
        crossed.push_back(patch.in);
        crossed.push_back(patch.out);
      }
    }
    const auto phases = static_cast<hsize_t>(stats.boundaryMass.size());
    const auto patches = static_cast<hsize_t>(engine_->boundaries().patches().size());
    f.writeDataset("/boundary_mass", crossed, {phases, patches, 2});
  });
}

std::unique_ptr<MfmEngine> MfmEngine::restore(const MultiFluidSetup& setup, const fs::path& stateFile,
                                              const std::string& fingerprint, const fs::path& outputDir,
                                              core::io::ArtifactStamp stamp) {
  std::unique_ptr<MfmEngine> e(new MfmEngine(setup, outputDir, std::move(stamp)));
  const auto f = core::io::openCheckpointFile(stateFile, {kCheckpointFormatVersion, fingerprint});
  fluid::readFlowState(f, "/", e->engine_->state());
  e->step_ = f.readIntAttribute("/", "step");
  e->engine_->timeStep().restore(f.readDoubleAttribute("/", "dt"));
  StepStatistics stats;
  stats.steps = f.readIntAttribute("/", "solver_steps");
  stats.retries = f.readIntAttribute("/", "retries");
  stats.iterations = f.readIntAttribute("/", "iterations");
  // Checkpoints written before the count was kept (issue 55) resume with it at zero.
  if (f.hasAttribute("/", "retried_iterations"))
    stats.retriedIterations = f.readIntAttribute("/", "retried_iterations");
  stats.lastDt = f.readDoubleAttribute("/", "last_dt");
  stats.tableCellSteps = f.readIntAttribute("/", "table_cell_steps");
  stats.coveredCellSteps = f.readIntAttribute("/", "covered_cell_steps");
  stats.tableSolidsSteps = f.readDoubleAttribute("/", "table_solids_steps");
  stats.coveredSolidsSteps = f.readDoubleAttribute("/", "covered_solids_steps");
  const std::size_t phases = e->engine_->state().phases.size();
  const std::size_t patches = e->engine_->boundaries().patches().size();
  stats.initialMass = f.readDoubles("/initial_mass", {phases});
  const std::vector<double> crossed = f.readDoubles("/boundary_mass", {phases, patches, 2});
  stats.boundaryMass.assign(phases, std::vector<fluid::PatchFlow>(patches));
  for (std::size_t m = 0; m < phases; ++m) {
    for (std::size_t p = 0; p < patches; ++p) {
      stats.boundaryMass[m][p] = {crossed[2 * (m * patches + p)], crossed[2 * (m * patches + p) + 1]};
    }
  }
  e->engine_->restoreStatistics(stats);
  return e;
}

}  // namespace grainbridge::mfm
