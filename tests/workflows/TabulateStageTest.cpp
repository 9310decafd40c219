// `tabulate`: closure points of a sweep become closure tables that load into
// core::ClosureTable; a hole in the grid or points of several frictions are refused, naming
// the state.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "tests/support/Cli.hpp"
#include "tests/support/TinyShear.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;
using nlohmann::json;
using ::testing::HasSubstr;

namespace {

// A few hundred steps of Lees-Edwards shear of 40 grains: enough for closure points, not physics.
json shear(json boxes, json restitutions, double mu = 0.0) {
  json params = tinyShearDemParams();
  params.erase("box_hi");
  params["contact"]["mu"] = mu;
  return {{"type", "dem"}, {"params", params}, {"sweep", {{"box_hi", boxes}, {"contact/restitution", restitutions}}}};
}

const json kBig = {"6 mm", "6 mm", "6 mm"};
const json kSmall = {"5 mm", "5 mm", "5 mm"};

// One extract stage per DEM stage (a per-instance stage with two upstream stages would pair
// their instances), all gathered by one tabulate.
json workflow(const json& dem) {
  json stages = dem;
  json extracts = json::array();
  for (const auto& [name, s] : dem.items()) {
    stages["x_" + name] = {{"type", "extract"}, {"from", name}, {"params", {{"family", "simple_shear"}}}};
    extracts.push_back("x_" + name);
  }
  stages["table"] = {{"type", "tabulate"}, {"from", extracts}, {"params", {{"table", "t"}}}};
  return {{"name", "tab"}, {"stages", stages}};
}

}  // namespace

TEST(TabulateStage, AFullGridLoadsAsATwoDimensionalClosureTable) {
  TempDir work;
  writeText(work.path() / "wf.json", workflow({{"shear", shear({kBig, kSmall}, {0.8, 0.9})}}).dump(2));
  const auto r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto database = db::Database::openReadOnly(work.path() / "results/tab/grainbridge.sqlite");
  db::ClosureStore store(database);
  const auto table = store.loadTable("t", "p_theta").table;
  ASSERT_TRUE(table.twoDimensional());
  EXPECT_EQ(table.solidFractions().size(), 2u);
  EXPECT_EQ(table.seconds(), (std::vector<double>{0.8, 0.9}));
  // The node values are the closure points' own p_theta.
  db::ClosureQuery q;
  for (const auto& p : store.query(q)) {
    const auto v = table(p["solid_fraction"].get<double>(), p["restitution"].get<double>());
    EXPECT_TRUE(v.inRange);
    EXPECT_NEAR(v.value, p["p_theta"].get<double>(), 1e-12 * std::abs(v.value));
  }
}

TEST(TabulateStage, AHoleInTheGridIsRefusedNamingTheMissingState) {
  TempDir work;
  // (big, 0.8), (small, 0.8) and (big, 0.9): no point at (small, 0.9).
  writeText(work.path() / "wf.json",
            workflow({{"a", shear({kBig, kSmall}, {0.8})}, {"b", shear({kBig}, {0.9})}}).dump(2));
  const auto r = runGrainbridge(work.path(), "run wf.json -q");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_THAT(r.output, HasSubstr("tabulate: no closure point at solid fraction"));
  EXPECT_THAT(r.output, HasSubstr("restitution 0.9: the table needs every combination of the 2 solid fractions"));
}

TEST(TabulateStage, PointsOfSeveralFrictionsNeedTheFrictionParameter) {
  TempDir work;
  json wf = workflow({{"a", shear({kBig}, {0.9}, 0.0)}, {"b", shear({kBig}, {0.9}, 0.5)}});
  writeText(work.path() / "wf.json", wf.dump(2));
  auto r = runGrainbridge(work.path(), "run wf.json -q");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_THAT(r.output, HasSubstr("/stages/table/params/friction: the points have 2 friction coefficients (0, 0.5)"));
  wf["stages"]["table"]["params"]["friction"] = 0.5;
  wf["stages"]["table"]["params"]["second_variable"] = "";
  writeText(work.path() / "wf.json", wf.dump(2));
  r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto database = db::Database::openReadOnly(work.path() / "results/tab/grainbridge.sqlite");
  EXPECT_FALSE(db::ClosureStore(database).loadTable("t", "p_theta").table.twoDimensional());
}
