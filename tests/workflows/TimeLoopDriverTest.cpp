// The time-loop driver gives any engine stage checkpoints, resume and a clean stop on SIGTERM
// with no code of its own for them. The toy engine here is a decaying scalar, dx/dt = -x/tau
// by explicit Euler, that writes one field frame per output: its stage is a setup and one
// observer, as an engine stage should be (docs/engine-stages.md).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/engine/SteppedEngine.hpp"
#include "core/io/FieldFrameReader.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "core/parallel/Communicator.hpp"
#include "tests/support/Cli.hpp"
#include "workflows/driver/TimeLoopDriver.hpp"
#include "workflows/stages/StageContext.hpp"

namespace fs = std::filesystem;
using namespace grainbridge;
using namespace grainbridge::workflows;
using grainbridge::testing::TempDir;

namespace {

constexpr double kDt = 1e-3;
constexpr double kTau = 0.5;
constexpr std::int64_t kSteps = 2000;

class DecayingScalar final : public core::engine::SteppedEngine {
 public:
  DecayingScalar(double x, double t, std::int64_t step, const fs::path& dir)
      : x_(x), t_(t), step_(step), writer_(dir, core::io::ArtifactStamp{"toy"}) {}

  void advance(bool) override {
    if (failAtStep_ == step_ + 1) throw Error("toy engine: x blew up");
    x_ -= kDt * x_ / kTau;
    t_ += kDt;
    ++step_;
  }
  [[nodiscard]] double time() const override { return t_; }
  [[nodiscard]] std::int64_t step() const override { return step_; }
  void saveState(const fs::path& file, const std::string& fingerprint) const override {
    std::ostringstream out;
    out << std::hexfloat << fingerprint << ' ' << x_ << ' ' << t_ << ' ' << step_;
    core::writeFileAtomically(file, out.str());
  }
  static std::unique_ptr<DecayingScalar> restore(const fs::path& file, const fs::path& dir) {
    std::istringstream in(core::readFile(file));
    std::string fingerprint, x, t;
    std::int64_t step = 0;
    in >> fingerprint >> x >> t >> step;
    return std::make_unique<DecayingScalar>(std::strtod(x.c_str(), nullptr), std::strtod(t.c_str(), nullptr), step,
                                            dir);
  }
  void writeFrames() override {
    core::data::FieldFrame f;
    f.time = t_;
    f.step = step_;
    f.grid.cells = {1, 1, 1};
    f.ep_g = {1.0};
    f.p_g = {x_};
    f.u_g = {Vec3::Zero()};
    writer_.write(f);
  }
  bool writeFramesIfUsable() override {
    if (!std::isfinite(x_)) return false;
    writeFrames();
    return true;
  }
  [[nodiscard]] std::string workItem() const override { return "cell"; }
  [[nodiscard]] std::int64_t workItems() const override { return 1; }

  [[nodiscard]] double x() const { return x_; }
  std::int64_t failAtStep_ = -1;

 private:
  double x_, t_;
  std::int64_t step_;
  core::io::FieldFrameWriter writer_;
};

// The series column x; it can also play the batch system (raise the stop flag) or a crash
// (throw) at a given step, the way a signal or a kill would arrive between steps.
class ScalarColumn final : public driver::SeriesColumns {
 public:
  ScalarColumn(const DecayingScalar& engine, std::atomic<bool>& stop) : engine_(engine), stop_(stop) {}
  [[nodiscard]] std::vector<std::string> names() const override { return {"x"}; }
  void sample(driver::SeriesRow& row) override {
    row.add(engine_.x());
    if (engine_.step() == stopAt) stop_ = true;
    if (engine_.step() == crashAt) throw std::runtime_error("killed");
  }
  std::int64_t stopAt = -1;
  std::int64_t crashAt = -1;

 private:
  const DecayingScalar& engine_;
  std::atomic<bool>& stop_;
};

struct ToyRun {
  std::int64_t stopAt = -1;
  std::int64_t crashAt = -1;
  std::int64_t failAt = -1;
  double checkpointEvery = 600.0;
  std::int64_t pollEvery = 256;
};

// The whole toy stage: setup, one observer, the driver. Returns the context for its artifacts.
std::unique_ptr<stages::StageContext> runToyStage(const fs::path& dir, const ToyRun& how,
                                                  const std::string& key = "toy") {
  static core::parallel::Communicator self = core::parallel::Communicator::self();
  static std::atomic<bool> stop;
  stop = false;
  auto ctx = std::make_unique<stages::StageContext>("wf", "decay", key, nlohmann::json::object(), dir,
                                                    std::vector<stages::UpstreamInstance>{}, self,
                                                    core::units::UnitSystem::si(), stop);
  driver::TimeLoopOptions options;
  options.frames = 4;
  options.seriesRows = 100;
  options.checkpointEvery = std::chrono::duration<double>(how.checkpointEvery);
  options.progress = false;
  options.pollEvery = how.pollEvery;
  driver::TimeLoopDriver loop(*ctx, options);
  auto engine = loop.start<DecayingScalar>([&] { return std::make_unique<DecayingScalar>(1.0, 0.0, 0, dir); },
                                           [&](const fs::path& state) { return DecayingScalar::restore(state, dir); });
  engine->failAtStep_ = how.failAt;
  loop.addPhase({.name = "run", .steps = kSteps, .output = true, .enter = {}, .configure = {}, .leave = {}});
  auto column = std::make_unique<ScalarColumn>(*engine, stop);
  column->stopAt = how.stopAt;
  column->crashAt = how.crashAt;
  loop.addColumns(std::move(column));
  loop.run(*engine);
  return ctx;
}

std::string frameData(const fs::path& dir) {
  std::ostringstream out;
  out.precision(17);
  for (const auto& f : core::io::listFieldFrames(dir)) {
    const auto frame = core::io::readFieldFrame(f);
    out << frame.step << ' ' << frame.time << ' ' << frame.p_g.at(0) << '\n';
  }
  return out.str();
}

class TimeLoopDriverTest : public ::testing::Test {
 protected:
  void SetUp() override { runToyStage(reference.path(), {}); }
  TempDir reference;
  TempDir work;
};

TEST_F(TimeLoopDriverTest, AnUninterruptedRunWritesTheScheduleAndRegistersItsArtifacts) {
  const auto ctx = runToyStage(work.path(), {});
  // The initial frame and 4 evenly spaced ones; a series row on 100 evenly spaced steps.
  EXPECT_EQ(core::io::listFieldFrames(work.path()).size(), 5u);
  const std::string series = core::readFile(work.path() / "series.csv");
  EXPECT_EQ(std::count(series.begin(), series.end(), '\n'), 101);
  EXPECT_EQ(series.substr(0, series.find('\n')), "time,step,x");
  // The last row is the end state: x = (1 - dt/tau)^n.
  const std::string lastRow = series.substr(series.rfind('\n', series.size() - 2) + 1);
  EXPECT_EQ(lastRow.substr(lastRow.find(',') + 1, lastRow.rfind(',') - lastRow.find(',') - 1), "2000");
  EXPECT_NEAR(std::stod(lastRow.substr(lastRow.rfind(',') + 1)), std::pow(1.0 - kDt / kTau, kSteps), 1e-15);
  std::map<std::string, int> kinds;
  for (const auto& a : ctx->artifacts()) ++kinds[a.kind];
  EXPECT_EQ(kinds["field_frame"], 5);
  EXPECT_EQ(kinds["xdmf"], 1);
  EXPECT_EQ(kinds["series_csv"], 1);
  EXPECT_EQ(kinds.count("particle_frame"), 0u);
  EXPECT_FALSE(fs::exists(work.path() / "checkpoint"));  // complete: the checkpoint has served
}

TEST_F(TimeLoopDriverTest, SigtermCheckpointsStopsAndTheResumedRunIsBitIdentical) {
  EXPECT_THROW(runToyStage(work.path(), {.stopAt = 740}), stages::StageInterrupted);
  // The stop is seen at the next poll (every 256 steps): step 768.
  ASSERT_TRUE(fs::exists(work.path() / "checkpoint/driver.json"));
  EXPECT_NE(core::readFile(work.path() / "checkpoint/driver.json").find("\"phase_step\": 768"), std::string::npos);
  EXPECT_FALSE(fs::exists(work.path() / "series.csv"));
  runToyStage(work.path(), {});
  EXPECT_EQ(core::readFile(work.path() / "series.csv"), core::readFile(reference.path() / "series.csv"));
  EXPECT_EQ(frameData(work.path()), frameData(reference.path()));
}

TEST_F(TimeLoopDriverTest, AnEngineOfCoarseStepsIsPolledEveryStep) {
  // An mfm step is a whole output interval: polled every step, the stop (flagged at the series
  // row of step 40) is seen at that step, not at step 256.
  EXPECT_THROW(runToyStage(work.path(), {.stopAt = 40, .pollEvery = 1}), stages::StageInterrupted);
  EXPECT_NE(core::readFile(work.path() / "checkpoint/driver.json").find("\"phase_step\": 40"), std::string::npos);
  runToyStage(work.path(), {.pollEvery = 1});
  EXPECT_EQ(core::readFile(work.path() / "series.csv"), core::readFile(reference.path() / "series.csv"));
  EXPECT_EQ(frameData(work.path()), frameData(reference.path()));
}

TEST_F(TimeLoopDriverTest, AfterACrashTheRunResumesFromTheLastPeriodicCheckpoint) {
  // A checkpoint at every poll; the process dies at step 1500, after the one at step 1280.
  EXPECT_THROW(runToyStage(work.path(), {.crashAt = 1500, .checkpointEvery = 0.0}), std::runtime_error);
  EXPECT_NE(core::readFile(work.path() / "checkpoint/driver.json").find("\"phase_step\": 1280"), std::string::npos);
  // One checkpoint's files only: the older ones were removed once the newer was registered.
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(work.path() / "checkpoint")) ++files;
  EXPECT_EQ(files, 3);  // driver.json, state-<n>.ckpt, series-<n>.csv
  runToyStage(work.path(), {});
  EXPECT_EQ(core::readFile(work.path() / "series.csv"), core::readFile(reference.path() / "series.csv"));
  EXPECT_EQ(frameData(work.path()), frameData(reference.path()));
}

TEST_F(TimeLoopDriverTest, AFailedStepKeepsTheLastGoodStateAndSaysWhere) {
  try {
    runToyStage(work.path(), {.failAt = 1234});
    FAIL() << "the engine failure must reach the stage";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("toy engine: x blew up; frames up to step 1233 are kept in"),
              std::string::npos)
        << e.what();
  }
  const auto frames = core::io::listFieldFrames(work.path());
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(core::io::readFieldFrame(frames.back()).step, 1233);
}

TEST_F(TimeLoopDriverTest, ACheckpointOfAnotherConfigurationIsNeverResumed) {
  EXPECT_THROW(runToyStage(work.path(), {.stopAt = 300}), stages::StageInterrupted);
  try {
    runToyStage(work.path(), {}, "another-key");
    FAIL() << "a checkpoint of another stage key must be refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("another configuration"), std::string::npos) << e.what();
  }
}

}  // namespace
