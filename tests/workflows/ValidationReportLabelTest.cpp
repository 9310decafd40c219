// The validation report names the state a Brazil-nut figure comes from ("run 3: pack, seed 2,
// side-wall friction 0.5") from what the upstream dem run recorded in its summary, never from its
// params (DESIGN.md, "Stage contracts"); a run recorded before its summary carried the state is
// still named, without it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "db/ProvenanceStore.hpp"
#include "tests/support/Cli.hpp"
#include "workflows/report/ValidationReport.hpp"

namespace fs = std::filesystem;
using namespace grainbridge;
using namespace grainbridge::testing;
using nlohmann::json;

namespace {

// A finished run of `stage` with these params and summary, fed by the runs of `upstreamKeys`.
std::int64_t addRun(db::ProvenanceStore& provenance, std::int64_t invocation, const std::string& stage,
                    const std::string& type, const std::string& key, const json& params, const json& summary,
                    std::vector<std::string> upstreamKeys = {}) {
  db::RunRecord run;
  run.invocationId = invocation;
  run.workflow = "bnp";
  run.stage = stage;
  run.stageType = type;
  run.implVersion = 1;
  run.key = key;
  run.paramsJson = params.dump();
  run.instanceDir = stage + "/" + key;
  run.codeVersion = "0123abcd";
  run.host = "node01";
  run.upstreamKeys = std::move(upstreamKeys);
  const std::int64_t id = provenance.insertRun(run);
  provenance.finishRun(id, "done", "", summary.dump());
  return id;
}

// One Eq. 6.11 fit of all contacts, which the report lists with its run's state.
json forcePdfFit() {
  return {{"force_statistics",
           {{{"family", "bnp"},
             {"source", "contacts"},
             {"forces", 120},
             {"model", "eq6.11"},
             {"a", 2.4},
             {"beta", 1.3},
             {"b", 0.7}}}}};
}

TEST(ValidationReportLabel, NamesTheStateTheUpstreamRecordedNotItsParams) {
  TempDir work;
  const fs::path path = work.path() / "results/bnp/grainbridge.sqlite";
  {
    auto database = db::Database::open(path);
    db::ProvenanceStore provenance(database);
    db::ClosureStore closures(database);
    db::InvocationRecord invocation;
    invocation.workflow = "bnp";
    invocation.configPath = "bnp.json";
    invocation.configJson = "{}";
    const std::int64_t inv = provenance.insertInvocation(invocation);
    // Params that disagree with the summary: the label must show the summary's values.
    const json params = {{"seed", 7}, {"walls", {{{"kind", "cylinder"}, {"mu", 0.9}}}}};
    addRun(provenance, inv, "pack", "dem", "k-pack", params,
           {{"particles", 10}, {"seed", 2}, {"side_wall_friction", 0.5}});
    // The same params, recorded before the dem stage wrote its state into its summary.
    addRun(provenance, inv, "old", "dem", "k-old", params, {{"particles", 10}});
    const std::int64_t fromPack =
        addRun(provenance, inv, "forces", "extract", "k-forces", json::object(), json::object(), {"k-pack"});
    const std::int64_t fromOld =
        addRun(provenance, inv, "forces_old", "extract", "k-forces-old", json::object(), json::object(), {"k-old"});
    closures.insertRecords(fromPack, forcePdfFit());
    closures.insertRecords(fromOld, forcePdfFit());
    ASSERT_EQ(fromPack, 3);
    ASSERT_EQ(fromOld, 4);
  }
  const auto summary = workflows::report::writeValidationReport({"", {path}}, work.path() / "v.html");
  EXPECT_EQ(summary.reported, 6);  // a, beta and b of each fit
  const std::string csv = readText(work.path() / "v.csv");
  EXPECT_NE(csv.find("(run 3: pack, seed 2, side-wall friction 0.5, 120 forces)"), std::string::npos) << csv;
  EXPECT_NE(csv.find("(run 4: old, 120 forces)"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("seed 7"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("friction 0.9"), std::string::npos) << csv;
}

}  // namespace
