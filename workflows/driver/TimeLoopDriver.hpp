#pragma once
// The one time loop of every engine stage (dem today; mfm and tfdem next). A stage is its setup
// plus a few observers:
//
//   TimeLoopDriver loop(ctx, options);                  // options from the stage's params
//   auto engine = loop.start<MyEngine>(fresh, restore);  // from the last checkpoint, if any
//   loop.addPhase({.name = "run", .steps = n, .output = true});
//   loop.addColumns(std::make_unique<MyColumns>(*engine));
//   loop.run(*engine);                                   // then ctx.setSummary(...)
//
// The driver owns what is the same for every engine: the output schedule (the initial frame,
// `frames` evenly spaced frames and `series_rows` evenly spaced series rows, the last step
// always with one), checkpoints every `checkpointEvery` of wall-clock time and on SIGTERM (then
// StageInterrupted), resuming from the last registered checkpoint (CheckpointSlot), progress
// (percent, rate, ETA), the throughput log, keeping the last good state when a step fails, and
// the artifacts: frames, their XDMF collections and series.csv.
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/engine/SteppedEngine.hpp"
#include "workflows/driver/CheckpointSlot.hpp"
#include "workflows/driver/InstanceRun.hpp"
#include "workflows/driver/Phase.hpp"
#include "workflows/driver/SeriesColumns.hpp"

namespace grainbridge::workflows::driver {

struct TimeLoopOptions {
  std::int64_t frames = 0;      // frames after the initial one, evenly spaced over the output phase
  std::int64_t seriesRows = 1;  // series rows, evenly spaced over the output phase
  std::chrono::duration<double> checkpointEvery{600.0};
  bool progress = true;
  // Stops, checkpoints and progress are looked at every this many steps: 256 suits a DEM step (a
  // few microseconds); an engine whose step is a whole output interval (mfm) needs 1, or a
  // SIGTERM and a checkpoint due would wait 256 output intervals.
  std::int64_t pollEvery = 256;
};

class TimeLoopDriver {
 public:
  TimeLoopDriver(InstanceRun& run, TimeLoopOptions options);

  // Builds the engine: from the state of the last registered checkpoint of this instance when it
  // has one (`restore` gets the state file), otherwise `fresh`. The driver, not the stage,
  // decides which.
  template <class Engine>
  std::unique_ptr<Engine> start(const std::function<std::unique_ptr<Engine>()>& fresh,
                                const std::function<std::unique_ptr<Engine>(const std::filesystem::path&)>& restore) {
    resumeFrom_ = checkpoints_.last();
    return resumeFrom_ ? restore(resumeFrom_->state) : fresh();
  }
  [[nodiscard]] bool resuming() const { return resumeFrom_.has_value(); }

  void addPhase(Phase phase) { phases_.push_back(std::move(phase)); }
  void addColumns(std::unique_ptr<SeriesColumns> columns) { columns_.push_back(std::move(columns)); }

  // Runs every phase (from the resumed one on), then writes series.csv, registers the frames and
  // the series as artifacts and removes the checkpoints. Throws StageInterrupted after a
  // checkpoint on SIGTERM, grainbridge::Error when the engine fails.
  void run(core::engine::SteppedEngine& engine);

 private:
  void runPhase(core::engine::SteppedEngine& engine, std::size_t index, std::int64_t firstStep);
  void sampleSeries(const core::engine::SteppedEngine& engine);
  void checkpoint(const core::engine::SteppedEngine& engine, std::size_t phase, std::int64_t phaseStep);
  void registerArtifacts();
  // True on every rank of the instance when `mine` is true on any (one rank: `mine`).
  [[nodiscard]] bool onAllRanks(bool mine) const;
  [[nodiscard]] std::string header() const;

  InstanceRun& ctx_;
  TimeLoopOptions options_;
  CheckpointSlot checkpoints_;
  std::optional<CheckpointRecord> resumeFrom_;
  std::vector<Phase> phases_;
  std::vector<std::unique_ptr<SeriesColumns>> columns_;
  std::string series_;
  std::chrono::steady_clock::time_point lastCheckpoint_;
  bool leader_ = true;  // rank 0 of the instance: writes series.csv, checkpoints and artifacts
};

}  // namespace grainbridge::workflows::driver
