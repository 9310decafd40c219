// The instance task crosses the MPI rank boundary as JSON text (MpiDispatcher), the one place the
// closure tables it carries change form between the database and the stage: what a worker rebuilds
// must be what rank 0 loaded, bit for bit, since a closure sample's draw adds to those values and a
// worker's run must equal the serial executor's.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/Error.hpp"
#include "workflows/exec/InstanceTask.hpp"

using namespace grainbridge;
using namespace grainbridge::workflows;
using nlohmann::json;

namespace {

exec::InstanceTask taskWithTables() {
  exec::InstanceTask task;
  task.workflow = "w";
  task.stage = "bed";
  task.stageType = "mfm";
  task.key = "k";
  task.params = {{"closure", "table"}};
  task.sweepPoint = {{"boundaries/0/gas_inflow", 0.207}};
  task.sweepWritten = {{"boundaries/0/gas_inflow", "20.7 cm/s"}};
  task.units = json::object();
  task.instanceDir = "w/bed/k";
  task.group = {1};
  task.upstream.push_back({"table", "tabulate", "up", "w/table/up", json::object(), json::object()});
  // Values with every bit significant (1/3, 0.1), so a lossy text form would show.
  core::ClosureTable pressure("p_theta", {0.1, 0.2, 0.3}, "restitution", {0.7, 0.9},
                              {1.0 / 3.0, 2.0, 3.1, 0.1, 2.5, 3.5e-7});
  task.closureTables.push_back({"t",
                                "run-key",
                                core::contentSha256(pressure),
                                0.25,
                                std::move(pressure),
                                {0.1 / 3.0, 0.2, 0.3, 0.15, 0.25, 1e-9}});
  core::ClosureTable dissipation("j_theta", {0.05, 0.5}, {0.7, 1.0 / 7.0});
  task.closureTables.push_back({"t", "run-key", core::contentSha256(dissipation), 0.0, std::move(dissipation), {}});
  core::LoadedRheology rheology;
  rheology.name = "r";
  rheology.runKey = "run-key";
  rheology.diameter = 1.5e-3;
  rheology.density = 2526.0;
  rheology.rows.push_back({0.9, {1e-3, 1e-2}, {0.35, 0.45}, core::LoadedRheology::Fit{0.35, 0.6, 0.28}});
  rheology.sha256 = core::contentSha256(rheology);
  task.rheologies.push_back(rheology);
  return task;
}

}  // namespace

TEST(InstanceTask, ClosureTablesCrossTheRankBoundaryBitForBit) {
  const exec::InstanceTask task = taskWithTables();
  const exec::InstanceTask back = exec::InstanceTask::fromJson(json::parse(task.toJson().dump()));
  ASSERT_EQ(back.closureTables.size(), task.closureTables.size());
  for (std::size_t i = 0; i < task.closureTables.size(); ++i) {
    const auto& a = task.closureTables[i];
    const auto& b = back.closureTables[i];
    EXPECT_EQ(b.name, a.name);
    EXPECT_EQ(b.runKey, a.runKey);
    EXPECT_EQ(b.sha256, a.sha256);
    EXPECT_EQ(b.friction, a.friction);
    EXPECT_EQ(b.quantity(), a.quantity());
    EXPECT_EQ(b.table.secondVariable(), a.table.secondVariable());
    EXPECT_EQ(b.table.solidFractions(), a.table.solidFractions());
    EXPECT_EQ(b.table.seconds(), a.table.seconds());
    EXPECT_EQ(b.table.values(), a.table.values());
    EXPECT_EQ(b.uncertainties, a.uncertainties);
    // The interpolant is rebuilt from the same nodes: equal lookups between them.
    EXPECT_EQ(b.table(0.137, 0.81).value, a.table(0.137, 0.81).value);
    EXPECT_EQ(core::contentSha256(b.table), a.sha256);
  }
  ASSERT_EQ(back.rheologies.size(), 1u);
  EXPECT_EQ(json(back.rheologies[0]), json(task.rheologies[0]));
  EXPECT_EQ(core::contentSha256(back.rheologies[0]), task.rheologies[0].sha256);
  // The plan's sweep point of each upstream instance goes along (UpstreamInstance::setSweep).
  ASSERT_EQ(back.upstream.size(), 1u);
  EXPECT_EQ(back.upstream[0].sweepPoint, task.upstream[0].sweepPoint);
  EXPECT_EQ(back.sweepWritten, task.sweepWritten);
}

TEST(InstanceTask, AWorkerRefusesAMalformedTableNamingIt) {
  json j = taskWithTables().toJson();
  j["closure_tables"][1]["values"] = {1.0};
  try {
    (void)exec::InstanceTask::fromJson(j);
    FAIL() << "a table with one value on a two-node axis was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("j_theta"), std::string::npos) << e.what();
  }
}
