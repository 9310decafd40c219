// End-to-end behaviour of `grainbridge run` through the CLI, as a user sees it: caching and
// --force, what invalidates a stage key and what does not, failures and --keep-going, and
// SIGKILL at every boundary that matters followed by a clean re-run (DESIGN.md, workflow
// semantics and failure behaviour).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "db/Database.hpp"
#include "db/ProvenanceStore.hpp"
#include "tests/support/Cli.hpp"

namespace fs = std::filesystem;
using namespace grainbridge;
using namespace grainbridge::testing;
using nlohmann::json;

namespace {

json smallWorkflow() {
  return json::parse(R"({
    "name": "wf",
    "stages": {
      "gas": {"type": "particle_gas",
              "params": {"n_particles": 300, "diameter": "1 mm", "seed": 3, "progress": false},
              "sweep": {"solid_fraction": [0.05, 0.1]}},
      "rep": {"type": "report", "from": "gas"}
    }
  })");
}

std::vector<db::RunRecord> runs(const fs::path& work) {
  auto database = db::Database::openReadOnly(work / "results/wf/grainbridge.sqlite");
  return db::ProvenanceStore(database).runs("wf");
}

int countStage(const std::vector<db::RunRecord>& rs, const std::string& stage, const std::string& status = "done") {
  return static_cast<int>(
      std::count_if(rs.begin(), rs.end(), [&](const auto& r) { return r.stage == stage && r.status == status; }));
}

class WorkflowRun : public ::testing::Test {
 protected:
  void write(const json& cfg) { writeText(work.path() / "wf.json", cfg.dump(2)); }
  CommandResult run(const std::string& extra = "", const std::string& env = "") {
    return runGrainbridge(work.path(), "run wf.json " + extra, env);
  }
  TempDir work;
};

TEST_F(WorkflowRun, SecondRunDoesNoWorkAndSaysSo) {
  write(smallWorkflow());
  auto first = run();
  ASSERT_EQ(first.exitCode, 0) << first.output;
  EXPECT_EQ(runs(work.path()).size(), 3u);
  auto second = run();
  ASSERT_EQ(second.exitCode, 0) << second.output;
  EXPECT_NE(second.output.find("up to date"), std::string::npos) << second.output;
  EXPECT_NE(second.output.find("nothing to do"), std::string::npos) << second.output;
  EXPECT_EQ(runs(work.path()).size(), 3u);
}

TEST_F(WorkflowRun, ForceRerunsEverything) {
  write(smallWorkflow());
  ASSERT_EQ(run().exitCode, 0);
  auto forced = run("--force");
  ASSERT_EQ(forced.exitCode, 0) << forced.output;
  const auto rs = runs(work.path());
  EXPECT_EQ(countStage(rs, "gas"), 4);
  EXPECT_EQ(countStage(rs, "rep"), 2);
}

TEST_F(WorkflowRun, ReorderedKeysAndNonResultParamsInvalidateNothing) {
  write(smallWorkflow());
  ASSERT_EQ(run().exitCode, 0);
  // The same workflow written with keys in another order and a parameter declared not to
  // affect results changed: every instance stays cached.
  const std::string reordered = R"({
    "stages": {
      "rep": {"from": "gas", "type": "report", "params": {"title": "another title"}},
      "gas": {"sweep": {"solid_fraction": [0.05, 0.1]}, "type": "particle_gas",
              "params": {"progress": true, "seed": 3, "diameter": 0.001, "n_particles": 300}}
    },
    "name": "wf"
  })";
  writeText(work.path() / "wf.json", reordered);
  auto again = run();
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_NE(again.output.find("nothing to do"), std::string::npos) << again.output;
  EXPECT_EQ(runs(work.path()).size(), 3u);
}

TEST_F(WorkflowRun, PhysicsParameterChangeRerunsOnlyDownstream) {
  json cfg = smallWorkflow();
  cfg["stages"]["gas"]["sweep"]["solid_fraction"] = {0.05};
  cfg["stages"]["other"] = json::parse(
      R"({"type": "particle_gas", "params": {"n_particles": 50, "solid_fraction": 0.1, "progress": false}})");
  write(cfg);
  ASSERT_EQ(run().exitCode, 0);
  cfg["stages"]["gas"]["params"]["seed"] = 4;
  write(cfg);
  auto st = runGrainbridge(work.path(), "status wf.json --why gas");
  EXPECT_NE(st.output.find("parameter seed: 3 -> 4"), std::string::npos) << st.output;
  st = runGrainbridge(work.path(), "status wf.json --why rep");
  EXPECT_NE(st.output.find("upstream gas[solid_fraction=0.05] changed"), std::string::npos) << st.output;
  ASSERT_EQ(run().exitCode, 0);
  const auto rs = runs(work.path());
  EXPECT_EQ(countStage(rs, "gas"), 2);    // rerun
  EXPECT_EQ(countStage(rs, "rep"), 2);    // downstream of gas: rerun
  EXPECT_EQ(countStage(rs, "other"), 1);  // independent: cached
}

// A sweep point that never ran says so; it is not compared with a sibling point's run (issue 54:
// "key changed since run 2 ... restitution 0.8 -> 0.9" for a point that had never run).
TEST_F(WorkflowRun, WhyNamesANeverRunSweepPointAsNeverRun) {
  json cfg = smallWorkflow();
  write(cfg);
  ASSERT_EQ(run().exitCode, 0);
  cfg["stages"]["gas"]["sweep"]["solid_fraction"] = {0.05, 0.1, 0.15};
  write(cfg);
  const auto st = runGrainbridge(work.path(), "status wf.json --why gas");
  EXPECT_NE(st.output.find("gas[solid_fraction=0.15]: never run"), std::string::npos) << st.output;
  EXPECT_NE(st.output.find("gas[solid_fraction=0.05]: up to date"), std::string::npos) << st.output;
  EXPECT_EQ(st.output.find("key changed"), std::string::npos) << st.output;
}

// Results are found from the current folder (or --workdir); from another folder the commands say
// where they are instead of "never run" (issue 54).
TEST_F(WorkflowRun, ResultsBesideTheConfigAreNamedFromAnotherFolder) {
  write(smallWorkflow());
  ASSERT_EQ(run().exitCode, 0);
  TempDir elsewhere;
  const std::string config = (work.path() / "wf.json").string();
  auto st = runGrainbridge(elsewhere.path(), "status '" + config + "'");
  EXPECT_NE(st.output.find("results are found from the current folder (or --workdir), not from the config's"),
            std::string::npos)
      << st.output;
  EXPECT_NE(st.output.find("--workdir " + work.path().string()), std::string::npos) << st.output;
  const auto q = runGrainbridge(elsewhere.path(), "db runs --config '" + config + "'");
  EXPECT_EQ(q.exitCode, 2) << q.output;
  EXPECT_NE(q.output.find("exists; run from " + work.path().string()), std::string::npos) << q.output;
  st = runGrainbridge(elsewhere.path(), "status '" + config + "' --workdir '" + work.path().string() + "'");
  EXPECT_EQ(st.output.find("not from the config's"), std::string::npos) << st.output;
  EXPECT_NE(st.output.find("done"), std::string::npos) << st.output;
}

// `db show RUN`: the provenance with one artifacts line per kind; --files lists each file with its
// sha256 (issue 54: a DEM run's show was 945 lines of frame hashes).
TEST_F(WorkflowRun, DbShowSummarisesArtifactsAndListsThemWithFiles) {
  write(smallWorkflow());
  ASSERT_EQ(run().exitCode, 0);
  const auto rs = runs(work.path());
  const auto& gas = *std::find_if(rs.begin(), rs.end(), [](const auto& r) { return r.stage == "gas"; });
  const auto brief = runGrainbridge(work.path(), "db show " + std::to_string(gas.id) + " --config wf.json");
  ASSERT_EQ(brief.exitCode, 0) << brief.output;
  EXPECT_NE(brief.output.find("  artifacts  "), std::string::npos) << brief.output;
  EXPECT_NE(brief.output.find("(--files lists each file with its sha256)"), std::string::npos) << brief.output;
  EXPECT_EQ(brief.output.find("sha256 "), std::string::npos) << brief.output;
  const auto files = runGrainbridge(work.path(), "db show " + std::to_string(gas.id) + " --config wf.json --files");
  ASSERT_EQ(files.exitCode, 0) << files.output;
  EXPECT_NE(files.output.find("  artifact   "), std::string::npos) << files.output;
  EXPECT_NE(files.output.find("sha256 "), std::string::npos) << files.output;
}

TEST_F(WorkflowRun, MovedProjectStaysCached) {
  write(smallWorkflow());
  ASSERT_EQ(run().exitCode, 0);
  TempDir elsewhere;
  fs::copy(work.path(), elsewhere.path() / "moved", fs::copy_options::recursive);
  auto r = runGrainbridge(elsewhere.path() / "moved", "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("nothing to do"), std::string::npos) << r.output;
}

TEST_F(WorkflowRun, TamperedArtifactIsRerun) {
  write(smallWorkflow());
  ASSERT_EQ(run().exitCode, 0);
  const auto rs = runs(work.path());
  const auto& gas = *std::find_if(rs.begin(), rs.end(), [](const auto& r) { return r.stage == "gas"; });
  std::ofstream(work.path() / "results" / gas.instanceDir / "particles.xmf", std::ios::app) << "<!-- edited -->";
  auto r = run();
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(countStage(runs(work.path()), "gas"), 3);
}

TEST_F(WorkflowRun, FailedInstanceIsNeverCachedAndKeepGoingFinishesTheRest) {
  json cfg = smallWorkflow();
  // Random insertion cannot reach solid fraction 0.6: that instance fails at run time.
  cfg["stages"]["gas"]["sweep"]["solid_fraction"] = {0.6, 0.05};
  cfg["stages"]["gas"]["params"]["max_attempts"] = 20;
  write(cfg);
  auto r = run();
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("could not insert sphere"), std::string::npos) << r.output;
  auto rs = runs(work.path());
  EXPECT_EQ(countStage(rs, "gas", "failed"), 1);
  EXPECT_EQ(countStage(rs, "gas", "done"), 0);  // stopped after the first failure

  r = run("--keep-going");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  rs = runs(work.path());
  EXPECT_EQ(countStage(rs, "gas", "failed"), 2);  // not cached: tried again
  EXPECT_EQ(countStage(rs, "gas", "done"), 1);
  EXPECT_EQ(countStage(rs, "rep", "done"), 0);  // depends on the failed instance
  auto st = runGrainbridge(work.path(), "status wf.json");
  EXPECT_NE(st.output.find("failed"), std::string::npos) << st.output;
  EXPECT_NE(st.output.find("1 done"), std::string::npos) << st.output;
}

// Starts `grainbridge run wf.json` in the background of `work`; returns its pid once its first
// stage instance is claimed (a 'running' row exists).
long startInBackground(const fs::path& work) {
  runCommand("cd '" + work.string() + "' && (" + grainbridgeBinary() +
             " run wf.json > bg.log 2>&1 & echo $! > bg.pid)");
  const long pid = std::stol(readText(work / "bg.pid"));
  const fs::path dbFile = work / "results/wf/grainbridge.sqlite";
  for (int i = 0; i < 600; ++i) {
    if (fs::exists(dbFile)) {
      try {
        auto database = db::Database::openReadOnly(dbFile);
        for (const auto& r : db::ProvenanceStore(database).runs("wf")) {
          if (r.status == "running") return pid;
        }
      } catch (const std::exception&) {
        // not migrated yet
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ADD_FAILURE() << "background run never claimed a stage";
  return pid;
}

void waitForExit(long pid) { waitForProcessExit(pid); }

json slowWorkflow() {
  json cfg = smallWorkflow();
  cfg["stages"]["gas"]["params"]["n_particles"] = 200000;
  cfg["stages"]["gas"]["sweep"]["solid_fraction"] = {0.3};
  return cfg;
}

TEST_F(WorkflowRun, ConcurrentRunLeavesAClaimedInstanceToItsLiveHolder) {
  write(slowWorkflow());
  const long pid = startInBackground(work.path());
  auto second = run();
  EXPECT_EQ(second.exitCode, 1) << second.output;
  EXPECT_NE(second.output.find("being run by another live process"), std::string::npos) << second.output;
  auto st = runGrainbridge(work.path(), "status wf.json");
  EXPECT_NE(st.output.find("running"), std::string::npos) << st.output;
  waitForExit(pid);
  EXPECT_NE(readText(work.path() / "bg.log").find("2 ran"), std::string::npos) << readText(work.path() / "bg.log");
  auto third = run();
  EXPECT_EQ(third.exitCode, 0) << third.output;
  const auto rs = runs(work.path());
  EXPECT_EQ(countStage(rs, "gas"), 1);  // the second run did not duplicate the work
  EXPECT_EQ(countStage(rs, "rep"), 1);
}

TEST_F(WorkflowRun, SigtermStopsCleanlyAndRecordsTheInterruptedInstance) {
  write(slowWorkflow());
  const long pid = startInBackground(work.path());
  runCommand("kill -TERM " + std::to_string(pid));
  waitForExit(pid);
  const std::string log = readText(work.path() / "bg.log");
  EXPECT_NE(log.find("interrupted"), std::string::npos) << log;
  auto rs = runs(work.path());
  ASSERT_EQ(countStage(rs, "gas", "killed"), 1) << log;
  auto database = db::Database::openReadOnly(work.path() / "results/wf/grainbridge.sqlite");
  EXPECT_EQ(database.integrityCheck(), "ok");
  auto again = run();
  EXPECT_EQ(again.exitCode, 0) << again.output;
  EXPECT_EQ(countStage(runs(work.path()), "gas"), 1);
}

// SIGKILL at each boundary of a stage's life, then a plain re-run must complete, never use the
// killed run's partial output, and leave an intact database.
class KilledRun : public WorkflowRun, public ::testing::WithParamInterface<std::string> {};

TEST_P(KilledRun, RerunCompletesCleanly) {
  write(smallWorkflow());
  auto killed = run("", "GRAINBRIDGE_FAILPOINT=" + GetParam());
  EXPECT_EQ(killed.exitCode, 128 + 9) << killed.output;

  auto again = run();
  ASSERT_EQ(again.exitCode, 0) << again.output;
  const auto rs = runs(work.path());
  EXPECT_EQ(countStage(rs, "gas"), 2);
  EXPECT_EQ(countStage(rs, "rep"), 1);
  {
    // The run that was killed is recorded as such (db.commit:4 kills inside the transaction
    // that would have recorded the first instance's completion, after
    // the schema migration, the invocation and the first claim), and nothing stays 'running'.
    EXPECT_GE(countStage(rs, "gas", "killed") + countStage(rs, "rep", "killed"), 1);
  }
  EXPECT_EQ(countStage(rs, "gas", "running") + countStage(rs, "rep", "running"), 0);

  auto database = db::Database::openReadOnly(work.path() / "results/wf/grainbridge.sqlite");
  EXPECT_EQ(database.integrityCheck(), "ok");
  // Every recorded artifact of a done run exists under a final folder, never a .partial one.
  db::ProvenanceStore store(database);
  for (const auto& r : rs) {
    if (r.status != "done") continue;
    for (const auto& a : store.artifactsOfRun(r.id)) {
      EXPECT_EQ(a.path.find(".partial"), std::string::npos) << a.path;
      EXPECT_TRUE(fs::exists(work.path() / "results" / a.path)) << a.path;
    }
  }
  // No partial folder is left over after the successful re-run.
  for (const auto& e : fs::recursive_directory_iterator(work.path() / "results")) {
    EXPECT_EQ(e.path().string().find(".partial"), std::string::npos) << e.path();
  }
  auto third = run();
  EXPECT_NE(third.output.find("nothing to do"), std::string::npos) << third.output;
}

INSTANTIATE_TEST_SUITE_P(AtEachBoundary, KilledRun,
                         ::testing::Values("particle_gas.after_insert", "stage.after_run", "stage.before_rename",
                                           "stage.after_rename", "db.commit:4"),
                         [](const auto& p) {
                           std::string s = p.param;
                           std::replace(s.begin(), s.end(), '.', '_');
                           std::replace(s.begin(), s.end(), ':', '_');
                           return s;
                         });

TEST_F(WorkflowRun, KillAtRandomMomentsThenRerun) {
  json cfg = smallWorkflow();
  cfg["stages"]["gas"]["params"]["n_particles"] = 20000;
  cfg["stages"]["gas"]["sweep"]["solid_fraction"] = {0.05, 0.1, 0.15};
  write(cfg);
  for (int delayMs : {30, 120, 250, 400}) {
    runCommand("cd '" + work.path().string() + "' && (" + grainbridgeBinary() + " run wf.json -q & pid=$!; sleep " +
               std::to_string(delayMs / 1000.0) + "; kill -9 $pid; wait $pid) >/dev/null 2>&1");
  }
  auto again = run();
  ASSERT_EQ(again.exitCode, 0) << again.output;
  auto database = db::Database::openReadOnly(work.path() / "results/wf/grainbridge.sqlite");
  EXPECT_EQ(database.integrityCheck(), "ok");
  EXPECT_EQ(countStage(runs(work.path()), "rep"), 1);
}

}  // namespace
