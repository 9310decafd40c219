// Multi-process tests: real processes, because SQLite's locking is between processes (POSIX
// locks and the WAL shared memory), which threads of one process would not exercise.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "db/Database.hpp"
#include "db/Leases.hpp"
#include "db/ProvenanceStore.hpp"
#include "db/StageCache.hpp"
#include "tests/db/TestSupport.hpp"

namespace grainbridge::db {
namespace {

using test::countRows;
using test::sampleInvocation;
using test::sampleRun;
using test::TempDir;

constexpr int kRunsPerWriter = 500;
constexpr const char* kCrashChildEnv = "GRAINBRIDGE_TEST_CRASH_DB";

// Body of a forked writer; returns its exit code (the child must _exit, never return into
// GoogleTest).
int writeRuns(const std::filesystem::path& path, int writer) {
  try {
    Database db = Database::open(path);
    ProvenanceStore store(db);
    const auto invocationId = db.transaction([&](Database&) { return store.insertInvocation(sampleInvocation()); });
    for (int i = 0; i < kRunsPerWriter; ++i) {
      db.transaction([&](Database&) {
        RunRecord run = sampleRun(invocationId, "w" + std::to_string(writer) + "-" + std::to_string(i));
        run.upstreamKeys = {"upstream-" + std::to_string(i)};
        store.insertRun(run);
      });
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "writer %d: %s\n", writer, e.what());
    return 1;
  }
}

TEST(DbConcurrency, TwoProcessesWriting500RunsEachLoseNothing) {
  TempDir dir;
  const auto path = dir / "gb.sqlite";
  Database::open(path);  // created and migrated, then closed: no connection crosses fork()
  pid_t writers[2];
  for (int w = 0; w < 2; ++w) {
    writers[w] = ::fork();
    ASSERT_GE(writers[w], 0);
    if (writers[w] == 0) ::_exit(writeRuns(path, w));
  }
  for (pid_t pid : writers) {
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "writer " << pid << " status " << status;
  }
  Database db = Database::open(path);
  EXPECT_EQ(countRows(db, "runs"), 2 * kRunsPerWriter);
  EXPECT_EQ(countRows(db, "run_inputs"), 2 * kRunsPerWriter);
  EXPECT_EQ(countRows(db, "invocations"), 2);
  EXPECT_EQ(db.integrityCheck(), "ok");
}

// What the crashing child does: a whole stage completion in one transaction. It is expected
// to be SIGKILLed at the "db.commit" fail point, before COMMIT.
[[noreturn]] void runCrashingChild(const std::filesystem::path& path) {
  try {
    Database db = Database::open(path);
    db.transaction([](Database& d) {
      ProvenanceStore store(d);
      const auto invocationId = store.insertInvocation(sampleInvocation("child"));
      const auto runId = store.insertRun(sampleRun(invocationId, "child-key", "child"));
      store.addArtifact({0, runId, "child-key", "bed/child-key/a.h5", "frames", "00", 1});
      StageCache(d).record({"child-key", runId, "child", "bed", "bed/child-key", ""});
      Leases(d).claim("child-key", currentProcessHolder(runId), std::chrono::seconds(60));
    });
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crash child: %s\n", e.what());
    std::_Exit(2);
  }
  std::_Exit(3);  // the fail point did not fire
}

// Forks a child that re-executes this test binary on the current test only, with the fail
// point armed. Re-executing (rather than running in the forked copy) matters: failPoint()
// caches getenv on first use, and this process has already called it (the parent's own
// transactions), so a plain fork would inherit "unarmed" and never die.
int runChildKilledAtCommit(const std::filesystem::path& path) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string filter = std::string("--gtest_filter=") + info->test_suite_name() + "." + info->name();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setenv("GRAINBRIDGE_FAILPOINT", "db.commit", 1);
    ::setenv(kCrashChildEnv, path.c_str(), 1);
    const int devNull = ::open("/dev/null", O_WRONLY);
    if (devNull >= 0) ::dup2(devNull, STDOUT_FILENO);  // keep the child's GoogleTest banner out of the log
    ::execl("/proc/self/exe", "test_db", filter.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

void expectOnlyParentRows(const std::filesystem::path& path) {
  Database db = Database::open(path);
  EXPECT_EQ(db.schemaVersion(), Database::latestSchemaVersion());
  EXPECT_EQ(db.integrityCheck(), "ok");
  ProvenanceStore store(db);
  EXPECT_TRUE(store.invocations("child").empty());
  EXPECT_TRUE(store.runsOfKey("child-key").empty());
  EXPECT_EQ(countRows(db, "artifacts"), 0);
  EXPECT_EQ(countRows(db, "stage_cache"), 0);
  EXPECT_EQ(countRows(db, "leases"), 0);
}

TEST(DbCrash, ProcessKilledBeforeCommitLeavesNoTrace) {
  if (const char* childPath = std::getenv(kCrashChildEnv)) runCrashingChild(childPath);
  TempDir dir;
  const auto path = dir / "gb.sqlite";
  Database::open(path).transaction([](Database& d) { ProvenanceStore(d).insertInvocation(sampleInvocation()); });

  const int status = runChildKilledAtCommit(path);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "child status " << status;
  expectOnlyParentRows(path);
  Database db = Database::open(path);
  EXPECT_EQ(countRows(db, "invocations"), 1);  // the parent's row survived
}

TEST(DbCrash, ProcessKilledWhileMigratingLeavesAUsableFile) {
  if (const char* childPath = std::getenv(kCrashChildEnv)) runCrashingChild(childPath);
  TempDir dir;
  const auto path = dir / "gb.sqlite";
  // Fresh file: the child dies at the commit of the migration inside Database::open.
  const int status = runChildKilledAtCommit(path);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "child status " << status;
  {
    Database db = Database::openReadOnly(path);
    EXPECT_EQ(db.schemaVersion(), 0);  // the migration did not half-happen
  }
  expectOnlyParentRows(path);  // migrates cleanly now
}

}  // namespace
}  // namespace grainbridge::db
