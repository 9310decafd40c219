// A `dem` instance stopped by SIGTERM (a batch system's time limit) or killed with SIGKILL
// resumes from its checkpoint on the next `run`, and the result is bit for bit the result of an
// uninterrupted run: every artifact has the same sha256 (DESIGN.md failure behaviour; issue 4's
// exact restart).
#include <gtest/gtest.h>

#include <map>
#include <thread>

#include "db/Database.hpp"
#include "db/ProvenanceStore.hpp"
#include "tests/support/Cli.hpp"
#include "tests/support/WorkflowResults.hpp"

namespace fs = std::filesystem;
using namespace grainbridge;
using namespace grainbridge::testing;

namespace {

const char* kWorkflow = R"({
  "name": "wf",
  "units": {"system": "reduced", "d0": "1 mm", "m0": "1e-6 kg", "g": "9.81 m/s2"},
  "stages": {
    "bed": {"type": "dem", "params": {
      "box_lo": [0, 0, 0], "box_hi": [12, 12, 24], "periodic": "xy", "gravity": [0, 0, -1],
      "dt": 2e-4, "duration": 16, "frames": 4, "series_points": 50, "progress": false,
      "checkpoint_interval": "0.3 s",
      "species": [{"name": "small", "diameter": 1, "density": 1.91, "count": 900}],
      "contact": {"kn": 2e5, "gamma_n": 40, "mu": 0.5},
      "walls": [{"kind": "plane", "point": [0, 0, 0], "direction": [0, 0, 1],
                 "kn": 2e5, "gamma_n": 40, "gamma_t": 20, "mu": 0.5}]}}
  }
})";

// Starts a run in the background, waits `delayMs`, sends `signal`, waits for the process.
std::string interruptedRun(const fs::path& work, int delayMs, const std::string& signal) {
  runCommand("cd '" + work.string() + "' && (" + grainbridgeBinary() +
             " run wf.json > bg.log 2>&1 & echo $! > bg.pid)");
  const std::string pid = readText(work / "bg.pid");
  std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
  runCommand("kill -" + signal + " " + pid);
  waitForProcessExit(std::stol(pid));
  return readText(work / "bg.log");
}

class DemResume : public ::testing::Test {
 protected:
  void SetUp() override {
    writeText(reference.path() / "wf.json", kWorkflow);
    writeText(work.path() / "wf.json", kWorkflow);
    auto r = runGrainbridge(reference.path(), "run wf.json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
  }
  TempDir reference;
  TempDir work;
};

TEST_F(DemResume, AfterSigtermTheResumedRunIsBitIdentical) {
  const std::string log = interruptedRun(work.path(), 900, "TERM");
  ASSERT_NE(log.find("checkpoint written"), std::string::npos) << log;
  auto resumed = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming from the checkpoint at step"), std::string::npos) << resumed.output;
  EXPECT_EQ(artifactDigests(work.path()), [&] {
    // Same relative paths: both live under results/wf/bed/<same key>.
    return artifactDigests(reference.path());
  }());
}

TEST_F(DemResume, AfterSigkillTheRunResumesFromTheLastPeriodicCheckpoint) {
  interruptedRun(work.path(), 1800, "KILL");
  auto resumed = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming from the checkpoint at step"), std::string::npos) << resumed.output;
  EXPECT_EQ(artifactDigests(work.path()), artifactDigests(reference.path()));
  auto database = db::Database::openReadOnly(work.path() / "results/wf/grainbridge.sqlite");
  EXPECT_EQ(database.integrityCheck(), "ok");
}

// Section 6.2's preparation (hold, shake, relax) is a long phase of its own in the Brazil-nut
// runs: a crash during it resumes from the preparation checkpoint, not from scratch, and the
// result is again bit for bit that of an uninterrupted run.
const char* kPreparedWorkflow = R"({
  "name": "wf",
  "units": {"system": "reduced", "d0": "1 mm", "m0": "1e-6 kg", "g": "9.81 m/s2"},
  "stages": {
    "bed": {"type": "dem", "params": {
      "box_lo": [-5, -5, -1], "box_hi": [5, 5, 30], "gravity": [0, 0, -1],
      "dt": 2e-4, "duration": 1, "frames": 2, "series_points": 20, "progress": false,
      "checkpoint_interval": "1e-9 s",
      "species": [{"name": "small", "diameter": 1, "density": 1.91, "count": 300},
                  {"name": "large", "diameter": 3, "density": 1.91, "count": 1}],
      "place": [{"species": "large", "position": [0, 0, 1.5]}],
      "insert_lo": [-4, -4, 0], "insert_hi": [4, 4, 12],
      "preparation": {"hold_species": "large", "shake_amplitude": 0.1, "shake_frequency": 2,
                      "shake_duration": 1, "relax_duration": 1},
      "contact": {"kn": 2e5, "gamma_n": 40, "mu": 0.5},
      "walls": [{"kind": "plane", "point": [0, 0, 0], "direction": [0, 0, 1],
                 "kn": 2e5, "gamma_n": 40, "gamma_t": 20, "mu": 0.5},
                {"kind": "cylinder", "point": [0, 0, 0], "direction": [0, 0, 1], "radius": 4.5,
                 "kn": 2e5, "gamma_n": 40, "gamma_t": 20, "mu": 0.5}]}}
  }
})";

TEST(DemPreparationResume, ACrashDuringThePreparationResumesFromItsCheckpointBitForBit) {
  TempDir reference;
  TempDir work;
  writeText(reference.path() / "wf.json", kPreparedWorkflow);
  writeText(work.path() / "wf.json", kPreparedWorkflow);
  auto r = runGrainbridge(reference.path(), "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;

  // The third preparation checkpoint (step 768, inside the 5000 shaking steps) is followed by
  // a SIGKILL.
  auto crashed = runGrainbridge(work.path(), "run wf.json", "GRAINBRIDGE_FAILPOINT=engine.checkpoint:3");
  ASSERT_NE(crashed.exitCode, 0) << crashed.output;
  auto resumed = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming the preparation (shaking) from its checkpoint at step 768"), std::string::npos)
      << resumed.output;
  EXPECT_EQ(artifactDigests(work.path()), artifactDigests(reference.path()));
}

}  // namespace
