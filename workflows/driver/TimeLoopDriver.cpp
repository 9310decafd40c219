#include "workflows/driver/TimeLoopDriver.hpp"

#include <sstream>

#include "core/Error.hpp"
#include "core/FailPoint.hpp"
#include "core/Files.hpp"
#include "core/Log.hpp"
#include "core/Progress.hpp"
#include "core/io/FieldFrameReader.hpp"
#include "core/io/ParticleFrameReader.hpp"
#include "core/text/NumberText.hpp"

namespace grainbridge::workflows::driver {

namespace fs = std::filesystem;

namespace {

// True on `count` evenly spaced steps of 1..total, the last one included.
bool onSchedule(std::int64_t step, std::int64_t count, std::int64_t total) {
  return count > 0 && step * count / total != (step - 1) * count / total;
}

}  // namespace

TimeLoopDriver::TimeLoopDriver(InstanceRun& ctx, TimeLoopOptions options)
    : ctx_(ctx), options_(options), checkpoints_(ctx.checkpointDir(), ctx.key()) {
  // On an instance of several ranks (an engine that runs over them, LAMMPS) every rank runs this
  // loop in step; the first writes the files and shows the progress.
  leader_ = ctx_.comm().rank() == 0;
  if (!leader_) options_.progress = false;
}

bool TimeLoopDriver::onAllRanks(bool mine) const {
  if (ctx_.comm().size() == 1) return mine;
  int flag = mine ? 1 : 0;
  int any = 0;
  MPI_Allreduce(&flag, &any, 1, MPI_INT, MPI_MAX, ctx_.comm().raw());
  return any != 0;
}

std::string TimeLoopDriver::header() const {
  std::string h = "time,step";
  for (const auto& c : columns_) {
    for (const auto& name : c->names()) h += "," + name;
  }
  return h + "\n";
}

void TimeLoopDriver::run(core::engine::SteppedEngine& engine) {
  GB_ASSERT(!phases_.empty(), "an engine stage needs at least one phase");
  std::size_t firstPhase = 0;
  std::int64_t firstStep = 0;
  if (resumeFrom_) {
    firstPhase = resumeFrom_->phase;
    firstStep = resumeFrom_->phaseStep;
    series_ = resumeFrom_->series;
    GB_ASSERT(firstPhase < phases_.size(), "checkpoint of a phase this stage does not have");
    const Phase& phase = phases_[firstPhase];
    if (phase.output)
      spdlog::info("{}: resuming from the checkpoint at step {}", ctx_.stage(), engine.step());
    else
      spdlog::info("{}: resuming the {} from its checkpoint at step {}", ctx_.stage(), phase.name, engine.step());
  } else {
    series_ = header();
  }
  lastCheckpoint_ = std::chrono::steady_clock::now();
  for (std::size_t k = firstPhase; k < phases_.size(); ++k) runPhase(engine, k, k == firstPhase ? firstStep : 0);

  if (!leader_) return;
  core::writeFileAtomically(ctx_.outputDir() / "series.csv", series_);
  checkpoints_.clear();
  registerArtifacts();
}

void TimeLoopDriver::runPhase(core::engine::SteppedEngine& engine, std::size_t index, std::int64_t firstStep) {
  const Phase& phase = phases_[index];
  if (firstStep == 0 && phase.enter) phase.enter();
  if (phase.configure) phase.configure();
  if (phase.output && firstStep == 0) engine.writeFrames();  // the initial state
  std::optional<core::Progress> progress;
  if (options_.progress) {
    progress.emplace(phase.output ? ctx_.stage() : ctx_.stage() + " " + phase.name, static_cast<double>(phase.steps),
                     "steps", 10.0, static_cast<double>(firstStep));
  }
  const auto loopStart = std::chrono::steady_clock::now();
  const std::int64_t workStart = engine.workSteps();
  for (std::int64_t s = firstStep + 1; s <= phase.steps; ++s) {
    const bool frameStep = phase.output && onSchedule(s, options_.frames, phase.steps);
    const bool seriesStep = phase.output && (onSchedule(s, options_.seriesRows, phase.steps) || s == phase.steps);
    try {
      engine.advance(frameStep || seriesStep);
    } catch (const Error& e) {
      // Keep the last good state on disk next to the periodic frames (for an unusable state, the
      // last periodic frame is the good one).
      const bool kept = engine.writeFramesIfUsable();
      throw Error(std::string(e.what()) + "; frames up to step " + std::to_string(kept ? engine.step() : s - 1) +
                  " are kept in " + ctx_.outputDir().string());
    }
    if (seriesStep) sampleSeries(engine);
    if (frameStep) engine.writeFrames();
    // Not on a phase's last step: what is left there is bookkeeping, and a run resumed after its
    // last step would hold no observed state for the stage's summary.
    if (s % options_.pollEvery == 0 && s < phase.steps) {
      // The ranks of one instance decide together: a signal or a clock seen by one is acted on
      // by all, at the same step (a checkpoint is collective).
      const bool stop = onAllRanks(ctx_.stopRequested());
      const bool due = onAllRanks(std::chrono::steady_clock::now() - lastCheckpoint_ > options_.checkpointEvery);
      if (stop) {
        checkpoint(engine, index, s);  // a batch system's SIGTERM: save, then stop cleanly
        spdlog::warn("{}: stopped at step {} of {}{}; checkpoint written, the next run resumes here", ctx_.stage(), s,
                     phase.steps, phase.output ? "" : " of the " + phase.name);
        throw StageInterrupted{};
      }
      if (due) {
        checkpoint(engine, index, s);
        lastCheckpoint_ = std::chrono::steady_clock::now();
      }
      if (progress) progress->update(static_cast<double>(s));
    }
  }
  if (progress) progress->finish();
  if (phase.output || phase.timed) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loopStart).count();
    // The engine's own steps, each over all its work items: a multi-fluid output interval is many
    // solver steps, a TF-DEM gas step `substeps` DEM steps of every particle.
    const std::int64_t steps = engine.workSteps() - workStart;
    const double rate = static_cast<double>(steps) * static_cast<double>(engine.workItems()) / seconds;
    const std::string note = engine.throughputNote();
    // A timed phase without output names itself: "bed: settling: 33333 DEM steps of ...".
    spdlog::info("{}: {}{} {}s of {} {}s in {:.3f} s: {} {}-steps/s{}", ctx_.stage(),
                 phase.output ? "" : phase.name + ": ", steps, engine.workStep(), engine.workItems(),
                 engine.workItem(), seconds, core::humanNumber(rate, 4), engine.workItem(),
                 phase.output ? (note.empty() ? "" : ", " + note) : "");
  }
  if (phase.leave) phase.leave();
}

void TimeLoopDriver::sampleSeries(const core::engine::SteppedEngine& engine) {
  std::ostringstream row;
  row.precision(17);
  row << engine.time() << ',' << engine.step();
  SeriesRow values(row);
  for (const auto& c : columns_) c->sample(values);
  row << '\n';
  series_ += row.str();
}

void TimeLoopDriver::checkpoint(const core::engine::SteppedEngine& engine, std::size_t phase, std::int64_t phaseStep) {
  if (leader_) {
    checkpoints_.save(engine, phase, phaseStep, series_);
  } else {
    // The engine's state is saved collectively (LAMMPS's write_restart); the leader's engine
    // writes the file the register names, the others' write nothing.
    engine.saveState(ctx_.checkpointDir() / "state-of-a-worker-rank", ctx_.key());
  }
  core::failPoint("engine.checkpoint");
}

void TimeLoopDriver::registerArtifacts() {
  const auto& dir = ctx_.outputDir();
  const auto particleFrames = core::io::listParticleFrames(dir);
  for (const auto& f : particleFrames) ctx_.addArtifact(f.lexically_relative(dir).string(), "particle_frame");
  if (!particleFrames.empty()) ctx_.addArtifact("particles.xmf", "xdmf");
  const auto fieldFrames = core::io::listFieldFrames(dir);
  for (const auto& f : fieldFrames) ctx_.addArtifact(f.lexically_relative(dir).string(), "field_frame");
  if (!fieldFrames.empty()) ctx_.addArtifact("fields.xmf", "xdmf");
  ctx_.addArtifact("series.csv", "series_csv");
}

}  // namespace grainbridge::workflows::driver
