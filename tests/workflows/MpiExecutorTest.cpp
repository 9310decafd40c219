// The MPI executor (rank 0 schedules and is the only database writer, rank 1.. run instances)
// must leave the same database rows as the serial executor, host, pid, rank, rank-count and
// time columns aside (DESIGN.md, executors).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "db/Database.hpp"
#include "db/Statement.hpp"
#include "tests/support/Cli.hpp"

namespace fs = std::filesystem;
using namespace grainbridge;
using namespace grainbridge::testing;

namespace {

const char* kWorkflow = R"({
  "name": "wf",
  "stages": {
    "gas": {"type": "particle_gas", "params": {"n_particles": 400, "progress": false},
            "sweep": {"solid_fraction": [0.05, 0.1, 0.2], "seed": [1, 2]}},
    "rep": {"type": "report", "from": "gas"}
  }
})";

// `grainbridge <args>` in `dir` under mpirun with `ranks` ranks (as root in CI, more ranks than
// cores).
CommandResult runUnderMpirun(const fs::path& dir, int ranks, const std::string& args) {
  return runCommand("cd '" + dir.string() +
                    "' && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -np " +
                    std::to_string(ranks) + " --oversubscribe " + grainbridgeBinary() + " " + args);
}

// Rows of every table as sorted text, with per-process columns left out.
std::multiset<std::string> rows(const fs::path& dbFile) {
  auto database = db::Database::openReadOnly(dbFile);
  std::multiset<std::string> out;
  auto collect = [&](const std::string& table, const std::string& sql, int columns) {
    auto st = database.prepare(sql);
    while (st.step()) {
      std::string row = table;
      for (int c = 0; c < columns; ++c) row += "|" + (st.columnIsNull(c) ? std::string("NULL") : st.columnText(c));
      out.insert(row);
    }
  };
  collect("runs",
          "SELECT workflow, stage, stage_type, impl_version, key, params_json, instance_dir, code_version, code_dirty, "
          "status, error, summary_json FROM runs",
          12);
  collect("run_inputs", "SELECT r.key, i.upstream_key FROM run_inputs i JOIN runs r ON r.id = i.run_id", 2);
  collect("artifacts", "SELECT key, path, kind, sha256, bytes FROM artifacts", 5);
  collect("stage_cache", "SELECT key, workflow, stage, instance_dir FROM stage_cache", 4);
  collect("leases", "SELECT key FROM leases", 1);
  collect("invocations", "SELECT workflow, config_json, code_version, code_dirty, status FROM invocations", 5);
  return out;
}

TEST(MpiExecutor, TwoRanksGiveTheSameRowsAsSerial) {
  TempDir serial;
  TempDir parallel;
  writeText(serial.path() / "wf.json", kWorkflow);
  writeText(parallel.path() / "wf.json", kWorkflow);
  auto s = runGrainbridge(serial.path(), "run wf.json");
  ASSERT_EQ(s.exitCode, 0) << s.output;
  auto p = runUnderMpirun(parallel.path(), 2, "run wf.json");
  ASSERT_EQ(p.exitCode, 0) << p.output;

  const auto a = rows(serial.path() / "results/wf/grainbridge.sqlite");
  const auto b = rows(parallel.path() / "results/wf/grainbridge.sqlite");
  EXPECT_GT(a.size(),
            7u + 6u + 6u * 2 + 7u + 1u);  // runs, run_inputs, gas artifacts, cache, invocation, + rep's artifacts
  EXPECT_EQ(a, b);

  // The ranks column says who ran it: rank 0 serially, a worker under MPI.
  auto database = db::Database::openReadOnly(parallel.path() / "results/wf/grainbridge.sqlite");
  auto st = database.prepare("SELECT COUNT(*) FROM runs WHERE rank = 0");
  ASSERT_TRUE(st.step());
  EXPECT_EQ(st.columnInt64(0), 0);

  // A second MPI run finds everything cached.
  auto again = runUnderMpirun(parallel.path(), 2, "run wf.json");
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_NE(again.output.find("nothing to do"), std::string::npos) << again.output;
}

TEST(MpiExecutor, BadConfigMakesEveryRankExitTwo) {
  TempDir work;
  writeText(work.path() / "wf.json", R"({"name": "wf", "stages": {"g": {"type": "nope"}}})");
  auto r = runUnderMpirun(work.path(), 2, "run wf.json");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_FALSE(fs::exists(work.path() / "results"));
}

// The fluid solver petsc under the MPI executor (issue 58): each worker rank initialises PETSc on
// its own (PETSC_COMM_WORLD = MPI_COMM_SELF: the ranks reach their first solve at different times,
// so nothing collective may happen there), and every rank finalises it before MPI. Two instances of
// the Goldschmidt smoke bed on two worker ranks at once: the run ends cleanly, and each instance's
// summary is the serial run's to the bit (KSP on one rank is deterministic).
TEST(MpiExecutor, PetscSolvesOnWorkerRanksAsItDoesSerially) {
  TempDir serial;
  TempDir parallel;
  nlohmann::json config = nlohmann::json::parse(readText(sourceDir() / "configs/goldschmidt-mono-smoke.json"));
  config["stages"].erase("heights");
  auto& params = config["stages"]["bed"]["params"];
  params["duration"] = "0.03 s";
  params["average_from"] = "0.01 s";
  params["frames"] = 1;
  for (const char* family : {"momentum", "pressure", "fraction"}) params[std::string(family) + "_solver"] = "petsc";
  writeText(serial.path() / "wf.json", config.dump(2));
  writeText(parallel.path() / "wf.json", config.dump(2));
  auto s = runGrainbridge(serial.path(), "run wf.json");
  ASSERT_EQ(s.exitCode, 0) << s.output;
  auto p = runUnderMpirun(parallel.path(), 3, "run wf.json");
  ASSERT_EQ(p.exitCode, 0) << p.output;
  const auto summaries = [](const fs::path& dbFile) {
    auto database = db::Database::openReadOnly(dbFile);
    auto st = database.prepare("SELECT summary_json, rank FROM runs WHERE stage = 'bed' ORDER BY key");
    std::vector<std::pair<std::string, long long>> out;
    while (st.step()) out.emplace_back(st.columnText(0), st.columnInt64(1));
    return out;
  };
  const auto a = summaries(serial.path() / "results/goldschmidt-mono-smoke/grainbridge.sqlite");
  const auto b = summaries(parallel.path() / "results/goldschmidt-mono-smoke/grainbridge.sqlite");
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  std::set<long long> workers;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].first, b[k].first);
    workers.insert(b[k].second);
  }
  EXPECT_FALSE(workers.contains(0));  // rank 0 schedules
}

}  // namespace
