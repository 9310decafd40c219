// Rank 0's bookkeeping of a finished instance: when the closure database refuses the rows a
// stage reported, nothing of the completion is committed (no rows, no cache entry), the run is
// recorded as failed with the reason, and the instance is redone next time.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>

#include "core/json/StrictParse.hpp"
#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "db/ProvenanceStore.hpp"
#include "tests/support/Cli.hpp"
#include "workflows/exec/Bookkeeper.hpp"
#include "workflows/plan/Plan.hpp"

using namespace grainbridge;
using namespace grainbridge::workflows;
using nlohmann::json;
using ::testing::HasSubstr;

namespace {

config::WorkflowConfig workflow() {
  core::json::Diagnostics d;
  auto doc = core::json::parseStrict(R"({"name": "w", "stages": {
    "gas": {"type": "particle_gas", "params": {"n_particles": 10, "solid_fraction": 0.1}}}})",
                                     d);
  EXPECT_TRUE(doc.has_value()) << d.format("t");
  return config::parseWorkflow(*doc, "t", stages::StageRegistry::builtin());
}

// A closure point with every required column, at solid fraction `phi`.
json point(double phi) {
  return {{"family", "simple_shear"}, {"solid_fraction", phi}, {"diameter", 1e-3}, {"density", 2500.0}, {"frames", 4}};
}

struct Recorded {
  exec::InstanceOutcome outcome;
  std::size_t closurePoints = 0;
  bool cached = false;
  std::string runStatus, runError;
};

// Begins and records the workflow's one instance as Done with `records` in its manifest.
Recorded recordDone(const json& records) {
  grainbridge::testing::TempDir work;
  const auto config = workflow();
  const auto plan = plan::makePlan(config);
  const auto& inst = plan.instances.front();
  exec::InstanceTask task;
  task.workflow = config.name;
  task.stage = inst.stage;
  task.stageType = inst.type->name();
  task.key = inst.key;
  task.params = inst.params;
  task.instanceDir = inst.relativeDir(config.name);

  // The instance's published folder, as the runner leaves it: the cache check needs it, so a
  // missing cache entry below is the bookkeeping's doing, not a missing folder.
  std::filesystem::create_directories(work.path() / task.instanceDir);
  grainbridge::testing::writeText(work.path() / task.instanceDir / "manifest.json", "{}");
  auto database = db::Database::open(work.path() / "db.sqlite");
  Recorded r;
  {
    exec::Bookkeeper books(database, config, work.path(), 1, std::chrono::seconds(60), std::chrono::milliseconds(50));
    books.start();
    const auto begun = books.begin(inst, task, 0, 1);
    EXPECT_TRUE(begun.claimed);
    r.outcome.status = exec::InstanceOutcome::Status::Done;
    r.outcome.manifest = {{"artifacts", json::array()}, {"summary", json::object()}, {"records", records}};
    books.record(inst, task, begun.runId, r.outcome);
    r.cached = books.validCacheEntry(inst.key).has_value();
    books.finish("done");
  }
  db::ClosureQuery q;
  r.closurePoints = db::ClosureStore(database).query(q).size();
  const auto runs = db::ProvenanceStore(database).runs("w");
  EXPECT_EQ(runs.size(), 1u);
  if (!runs.empty()) {
    r.runStatus = runs.front().status;
    r.runError = runs.front().error;
  }
  return r;
}

}  // namespace

TEST(Bookkeeper, RecordsTheRowsOfAFinishedInstanceAndCachesIt) {
  const auto r = recordDone({{"closure_points", {point(0.1), point(0.2)}}});
  EXPECT_EQ(r.outcome.status, exec::InstanceOutcome::Status::Done);
  EXPECT_EQ(r.closurePoints, 2u);
  EXPECT_TRUE(r.cached);
  EXPECT_EQ(r.runStatus, "done");
}

TEST(Bookkeeper, RowsTheDatabaseRefusesFailTheRunAndCommitNothing) {
  // The second point breaks the schema's CHECK (a solid fraction of 1.5): the first, valid one
  // must not be committed either.
  const auto r = recordDone({{"closure_points", {point(0.1), point(1.5)}}});
  EXPECT_EQ(r.outcome.status, exec::InstanceOutcome::Status::Failed);
  EXPECT_THAT(r.outcome.error, HasSubstr("recording the results failed"));
  EXPECT_THAT(r.outcome.error, HasSubstr("closure_points/1"));
  EXPECT_EQ(r.closurePoints, 0u);
  EXPECT_FALSE(r.cached);  // redone next time
  EXPECT_EQ(r.runStatus, "failed");
  EXPECT_THAT(r.runError, HasSubstr("recording the results failed"));
}

TEST(Bookkeeper, ARowNamingAnUnknownColumnIsRefusedTheSameWay) {
  json bad = point(0.2);
  bad["presure"] = 1.0;
  const auto r = recordDone({{"closure_points", {bad}}});
  EXPECT_EQ(r.outcome.status, exec::InstanceOutcome::Status::Failed);
  EXPECT_THAT(r.outcome.error, HasSubstr("no column \"presure\""));
  EXPECT_EQ(r.closurePoints, 0u);
  EXPECT_FALSE(r.cached);
}
