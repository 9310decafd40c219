#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "db/Database.hpp"
#include "db/Leases.hpp"
#include "db/ProvenanceStore.hpp"
#include "tests/db/TestSupport.hpp"

namespace grainbridge::db {
namespace {

using test::sampleInvocation;
using test::sampleRun;
using test::TempDir;
using ::testing::HasSubstr;

TEST(ProvenanceStore, InvocationRoundTrip) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  ProvenanceStore store(db);
  InvocationRecord invocation = sampleInvocation();
  invocation.id = db.transaction([&](Database&) { return store.insertInvocation(invocation); });
  store.insertInvocation(sampleInvocation("other"));

  const auto shear = store.invocations("shear");
  ASSERT_EQ(shear.size(), 1u);
  EXPECT_EQ(shear[0], invocation);
  EXPECT_EQ(store.invocations("").size(), 2u);

  store.finishInvocation(invocation.id, "done");
  const InvocationRecord finished = store.invocations("shear").at(0);
  EXPECT_EQ(finished.status, "done");
  EXPECT_FALSE(finished.endedAt.empty());
  EXPECT_THROW(store.finishInvocation(999, "done"), Error);
}

TEST(ProvenanceStore, DefaultsStatusStartTimeAndNullColumns) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  ProvenanceStore store(db);
  InvocationRecord invocation = sampleInvocation();
  invocation.status.clear();
  invocation.startedAt.clear();
  invocation.configPath.clear();
  const auto id = store.insertInvocation(invocation);
  const InvocationRecord stored = store.invocations("").at(0);
  EXPECT_EQ(stored.status, "running");
  EXPECT_FALSE(stored.startedAt.empty());
  Statement nulls = db.prepare("SELECT config_path IS NULL, ended_at IS NULL FROM invocations WHERE id=?");
  nulls.bind(1, id);
  ASSERT_TRUE(nulls.step());
  EXPECT_EQ(nulls.columnInt64(0), 1);
  EXPECT_EQ(nulls.columnInt64(1), 1);
}

TEST(ProvenanceStore, RunWithUpstreamKeysAndArtifactsRoundTrip) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  ProvenanceStore store(db);
  const auto invocationId = store.insertInvocation(sampleInvocation());

  RunRecord run = sampleRun(invocationId, "key-extract");
  run.stage = "extract";
  run.upstreamKeys = {"key-bed-b", "key-bed-a"};  // order is kept
  run.id = store.insertRun(run);
  RunRecord other = sampleRun(invocationId, "key-bed-a");
  other.id = store.insertRun(other);

  ASSERT_TRUE(store.run(run.id).has_value());
  EXPECT_EQ(*store.run(run.id), run);
  EXPECT_FALSE(store.run(run.id + 100).has_value());
  EXPECT_EQ(store.runs("shear"), (std::vector<RunRecord>{run, other}));
  EXPECT_TRUE(store.runs("nope").empty());
  EXPECT_EQ(store.runs("").size(), 2u);

  const ArtifactRecord frames{0, run.id, run.key, "extract/key-extract/closures.h5", "closures", "abc123", 2048};
  const ArtifactRecord manifest{0, run.id, run.key, "extract/key-extract/manifest.json", "manifest", "def456", 300};
  db.transaction([&](Database&) {
    store.addArtifact(frames);
    store.addArtifact(manifest);
  });
  const auto artifacts = store.artifactsOfRun(run.id);
  ASSERT_EQ(artifacts.size(), 2u);
  EXPECT_GT(artifacts[0].id, 0);
  ArtifactRecord expected = frames;
  expected.id = artifacts[0].id;
  EXPECT_EQ(artifacts[0], expected);
  EXPECT_EQ(artifacts[1].path, manifest.path);
  EXPECT_TRUE(store.artifactsOfRun(other.id).empty());
  EXPECT_THROW(store.addArtifact(frames), Error);  // UNIQUE(run_id, path)

  store.finishRun(run.id, "done", "", R"({"frames":40})");
  const RunRecord done = *store.run(run.id);
  EXPECT_EQ(done.status, "done");
  EXPECT_EQ(done.error, "");
  EXPECT_EQ(done.summaryJson, R"({"frames":40})");
  EXPECT_FALSE(done.endedAt.empty());

  store.finishRun(other.id, "failed", "diverged at step 120", "");
  EXPECT_EQ(store.run(other.id)->error, "diverged at step 120");
  EXPECT_THROW(store.finishRun(12345, "done", "", ""), Error);
  EXPECT_THROW(store.finishRun(run.id, "finished", "", ""), Error);  // CHECK(status IN ...)
}

TEST(ProvenanceStore, RunsOfKeyListsReruns) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  ProvenanceStore store(db);
  const auto invocationId = store.insertInvocation(sampleInvocation());
  const auto first = store.insertRun(sampleRun(invocationId, "k"));
  store.insertRun(sampleRun(invocationId, "other"));
  const auto second = store.insertRun(sampleRun(invocationId, "k"));
  const auto runs = store.runsOfKey("k");
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].id, first);
  EXPECT_EQ(runs[1].id, second);
}

TEST(ProvenanceStore, RunOfMissingInvocationIsRefused) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  EXPECT_THROW(ProvenanceStore(db).insertRun(sampleRun(77, "k")), Error);
}

TEST(ProvenanceStore, MarksRunsWithDeadOrMissingLeasesKilled) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  ProvenanceStore store(db);
  Leases leases(db);
  const auto staleAfter = std::chrono::seconds(60);
  const auto invocationId = store.insertInvocation(sampleInvocation());

  LeaseHolder dead = test::deadHolder();
  RunRecord crashed = sampleRun(invocationId, "crashed");
  crashed.host = dead.host;
  crashed.pid = dead.pid;
  dead.runId = store.insertRun(crashed);
  ASSERT_TRUE(leases.claim("crashed", dead, staleAfter).claimed);

  const LeaseHolder me = currentProcessHolder(0);
  const auto liveRun = store.insertRun(sampleRun(invocationId, "live"));
  ASSERT_TRUE(leases.claim("live", me, staleAfter).claimed);
  ASSERT_TRUE(leases.setRun("live", me, liveRun));

  // Lease run_id unset: matched by key, host and pid.
  RunRecord unattached = sampleRun(invocationId, "unattached");
  unattached.host = me.host;
  unattached.pid = me.pid;
  const auto unattachedRun = store.insertRun(unattached);
  ASSERT_TRUE(leases.claim("unattached", me, staleAfter).claimed);

  const auto noLease = store.insertRun(sampleRun(invocationId, "no-lease"));
  const auto finished = store.insertRun(sampleRun(invocationId, "finished"));
  store.finishRun(finished, "done", "", "");

  EXPECT_EQ(db.transaction([&](Database&) { return store.markOrphanedRunsKilled(staleAfter); }), 2);
  const RunRecord killed = *store.run(dead.runId);
  EXPECT_EQ(killed.status, "killed");
  EXPECT_EQ(killed.error, "process " + dead.host + ":" + std::to_string(dead.pid) + " ended without finishing");
  EXPECT_FALSE(killed.endedAt.empty());
  EXPECT_EQ(store.run(noLease)->status, "killed");
  EXPECT_EQ(store.run(liveRun)->status, "running");
  EXPECT_EQ(store.run(unattachedRun)->status, "running");
  EXPECT_EQ(store.run(finished)->status, "done");
  EXPECT_EQ(store.markOrphanedRunsKilled(staleAfter), 0);
}

}  // namespace
}  // namespace grainbridge::db
