// `tabulate`: closure points of a sweep become closure tables that load into
// core::ClosureTable; a hole in the grid or points of several frictions are refused, naming
// the state.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "db/Statement.hpp"
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

TEST(TabulateStage, ShearedPointsGiveTheRheologyRowsThatDbQueryShows) {
  TempDir work;
  json wf = workflow({{"shear", shear({kBig, {"5.5 mm", "5.5 mm", "5.5 mm"}, kSmall, {"4.7 mm", "4.7 mm", "4.7 mm"}},
                                      {0.9})}});
  wf["stages"]["table"]["params"]["second_variable"] = "";
  wf["stages"]["table"]["params"]["fit_inertial_number_max"] = 1e3;  // tiny boxes: fit every point
  writeText(work.path() / "wf.json", wf.dump(2));
  auto r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  r = runGrainbridge(work.path(), "db query --config wf.json --table rheology --format json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const json rows = json::parse(r.output);
  ASSERT_EQ(rows.size(), 4U) << r.output;  // mu(I) and phi(I), each in two forms
  auto database = db::Database::openReadOnly(work.path() / "results/tab/grainbridge.sqlite");
  db::ClosureQuery q;
  const json points = db::ClosureStore(database).query(q);
  ASSERT_EQ(points.size(), 4U);
  for (const auto& row : rows) {
    EXPECT_EQ(row["points"], 4);
    EXPECT_EQ(row["fitted_points"], 4);
    EXPECT_DOUBLE_EQ(row["restitution"].get<double>(), 0.9);
    // The tabulated inertial numbers are the closure points' own, in increasing order.
    const auto I = json::parse(row["inertial_numbers_json"].get<std::string>()).get<std::vector<double>>();
    ASSERT_EQ(I.size(), 4U);
    EXPECT_TRUE(std::is_sorted(I.begin(), I.end()));
    for (const auto& p : points) {
      EXPECT_NE(std::find(I.begin(), I.end(), p["inertial_number"].get<double>()), I.end());
    }
    const bool power = row["form"].get<std::string>().find('^') != std::string::npos;
    if (row["relation"] == "phi_of_I" && !power) {
      EXPECT_EQ(row["form"], "phi_c - slope I");
      EXPECT_TRUE(row.contains("phi_c") && row["phi_c"].is_number()) << row.dump();
      EXPECT_TRUE(row.contains("slope_err") && row["slope_err"].is_number()) << row.dump();
    } else if (!power) {
      EXPECT_EQ(row["relation"], "mu_of_I");
      EXPECT_EQ(row["form"], "mu_s + (mu_2 - mu_s) / (1 + I_0 / I)");
    }
  }
  // 0.02 s of 40 grains is noise, not rheology: mu(I) need not fit. The table is still made, and
  // a missing fit is said in the stage's summary rather than failing the stage.
  auto st = database.prepare("SELECT summary_json FROM runs WHERE stage = 'table' AND status = 'done'");
  ASSERT_TRUE(st.step());
  const json summary = json::parse(st.columnText(0));
  EXPECT_EQ(summary["rheology_rows"], 4) << summary.dump();
  // The power laws (3 parameters on 4 noisy points): fitted, or why not.
  EXPECT_TRUE(summary.contains("phi_c_power") || summary.value("phi_of_I_power_fit", "").starts_with("none:"))
      << summary.dump();
  EXPECT_TRUE(summary.contains("phi_c") && summary.contains("phi_c_err")) << summary.dump();
  EXPECT_TRUE(summary.contains("mu_s") || summary.value("mu_of_I_fit", "").starts_with("none: the mu_of_I fit"))
      << summary.dump();
}

TEST(TabulateStage, PressureControlledPointsExtendTheTableToTheirMeasuredSolidFractions) {
  TempDir work;
  json wf = workflow({{"cv", shear({kBig, kSmall}, {0.9})}});
  json pc = tinyShearDemParams();
  // Narrow in x and z, so that the packed slab stays thicker than twice the interaction range.
  pc["box_hi"] = {"3.2 mm", "6 mm", "3.2 mm"};
  pc["pressure_control"] = {{"stress", "500 Pa"}, {"relaxation_time", "2e-3 s"}};
  wf["stages"]["pc"] = {{"type", "dem"}, {"params", pc}};
  wf["stages"]["x_pc"] = {{"type", "extract"}, {"from", "pc"}, {"params", {{"family", "simple_shear"}}}};
  wf["stages"]["table"]["from"].push_back("x_pc");
  wf["stages"]["table"]["params"]["second_variable"] = "";
  writeText(work.path() / "wf.json", wf.dump(2));
  const auto r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto database = db::Database::openReadOnly(work.path() / "results/tab/grainbridge.sqlite");
  db::ClosureStore store(database);
  const auto table = store.loadTable("t", "p_theta").table;
  ASSERT_EQ(table.solidFractions().size(), 3U);
  // The pressure-controlled box's point sits at its measured (time-averaged) solid fraction,
  // with its own p_theta, beside the two constant-volume ones.
  db::ClosureQuery q;
  const json points = store.query(q);
  ASSERT_EQ(points.size(), 3U);
  for (const auto& p : points) {
    const auto v = table(p["solid_fraction"].get<double>());
    EXPECT_TRUE(v.inRange);
    EXPECT_NEAR(v.value, p["p_theta"].get<double>(), 1e-12 * std::abs(v.value));
  }
}

// Issue 61: a point whose box is crystalline (an fcc lattice of 108 grains at solid fraction 0.68,
// sheared for a quarter of a strain unit) is recorded as ordered and left out of the tables unless
// keep_ordered; the random gas's points are tabled either way. compare draws the ordered point
// apart and counts it.
TEST(TabulateStage, AnOrderedBoxIsRecordedAndLeftOutUnlessKeepOrdered) {
  TempDir work;
  json lattice = shear({kBig}, {0.9});
  lattice["params"]["insertion"] = "fcc_lattice";
  lattice["params"]["species"][0]["count"] = 108;
  // A quarter strain: the crystal holds (crystalline share 0.98 whatever the skin). By half a
  // strain it has begun to melt, and how far depends on round-off: 0.68-0.98 over skins of
  // 0.2-0.35, which only move the list builds.
  lattice["params"]["duration"] = "0.0025 s";
  lattice["sweep"] = {{"box_hi", {{"4.37 mm", "4.37 mm", "4.37 mm"}}}, {"contact/restitution", {0.9}}};
  json wf = workflow({{"gas", shear({kBig, kSmall}, {0.9})}, {"lattice", lattice}});
  wf["stages"]["table"]["params"]["second_variable"] = "";
  wf["stages"]["cmp"] = {{"type", "compare"}, {"from", wf["stages"]["table"]["from"]}};
  writeText(work.path() / "wf.json", wf.dump(2));
  auto r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  {
    auto database = db::Database::openReadOnly(work.path() / "results/tab/grainbridge.sqlite");
    auto st = database.prepare("SELECT summary_json FROM runs WHERE stage = 'cmp' AND status = 'done'");
    ASSERT_TRUE(st.step());
    const json compared = json::parse(st.columnText(0));
    EXPECT_EQ(compared["points"], 3) << compared.dump();
    EXPECT_EQ(compared["ordered_points"], 1) << compared.dump();
    db::ClosureStore store(database);
    int ordered = 0;
    for (const auto& p : store.query({})) {
      const bool crystal = p["ordered"].get<int>() == 1;
      ordered += crystal ? 1 : 0;
      EXPECT_EQ(crystal, p["solid_fraction"].get<double>() > 0.6) << p.dump();
      if (crystal) {
        EXPECT_GT(p["crystalline_share"].get<double>(), 0.9);
      }
    }
    EXPECT_EQ(ordered, 1);
    EXPECT_EQ(store.loadTable("t", "p_theta").table.solidFractions().size(), 2u);
  }
  EXPECT_THAT(r.output, HasSubstr("its box ordered"));
  wf["stages"]["table"]["params"]["keep_ordered"] = true;
  writeText(work.path() / "wf.json", wf.dump(2));
  r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto database = db::Database::openReadOnly(work.path() / "results/tab/grainbridge.sqlite");
  EXPECT_EQ(db::ClosureStore(database).loadTable("t", "p_theta").table.solidFractions().size(), 3u);
}

// A mixture species' table over (total solid fraction, volume share, restitution) (issue 60):
// two compositions of a 1 and 2 mm pair at equal solids volume (8 + 3 and 24 + 1 grains: x 0.25
// and 0.75), two boxes, two restitutions, one table of 2 x 2 x 2 nodes, each the species' point.
TEST(TabulateStage, ASpeciesTableTakesRestitutionAsItsThirdAxis) {
  auto binary = [](int small, int large) {
    json s = shear({{"7 mm", "7 mm", "7 mm"}, kBig}, {0.8, 0.9});
    s["params"]["species"] = {{{"name", "small"}, {"diameter", "1 mm"}, {"density", "2500 kg/m3"}, {"count", small}},
                              {{"name", "large"}, {"diameter", "2 mm"}, {"density", "2500 kg/m3"}, {"count", large}}};
    return s;
  };
  json wf = workflow({{"x25", binary(8, 3)}, {"x75", binary(24, 1)}});
  for (const char* x : {"x_x25", "x_x75"}) wf["stages"][x]["params"]["family"] = "simple_shear_binary";
  wf["stages"]["table"]["params"] = {
      {"table", "pair"}, {"species", "small"}, {"second_variable", "volume_share"}, {"third_variable", "restitution"}};
  TempDir work;
  writeText(work.path() / "wf.json", wf.dump(2));
  const auto r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto database = db::Database::openReadOnly(work.path() / "results/tab/grainbridge.sqlite");
  db::ClosureStore store(database);
  const auto table = store.loadTable("pair", "p_theta").table;
  ASSERT_TRUE(table.threeDimensional());
  EXPECT_EQ(table.solidFractions().size(), 2u);
  ASSERT_EQ(table.seconds().size(), 2u);
  EXPECT_NEAR(table.seconds()[0], 0.25, 1e-12);
  EXPECT_NEAR(table.seconds()[1], 0.75, 1e-12);
  EXPECT_EQ(table.thirds(), (std::vector<double>{0.8, 0.9}));
  db::ClosureQuery q;
  q.ranges.push_back({"species", std::nullopt, std::nullopt, "small"});
  const auto points = store.query(q);
  ASSERT_EQ(points.size(), 8u);
  for (const auto& p : points) {
    // A node is its points' state to 1e-4 (integer grain counts): one at an edge may lie a few
    // ulps outside and read the edge node, which is its own value.
    const auto v = table(p["mixture_solid_fraction"].get<double>(), p["volume_share"].get<double>(),
                         p["restitution"].get<double>());
    EXPECT_NEAR(v.value, p["p_theta"].get<double>(), 1e-12 * std::abs(v.value));
  }
  // The third axis takes every restitution: a restitution filter beside it is refused at check.
  wf["stages"]["table"]["params"]["restitution"] = 0.9;
  writeText(work.path() / "bad.json", wf.dump(2));
  const auto bad = runGrainbridge(work.path(), "check bad.json");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_THAT(bad.output, HasSubstr("/stages/table/params/restitution: the table's third axis is restitution"));
}
