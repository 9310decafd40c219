// `grainbridge db query` and `db export` on a closure database: filters by family, state range
// and run; table, CSV and JSON output; a clear usage error (exit 2) for an unknown column.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "db/ProvenanceStore.hpp"
#include "tests/db/TestSupport.hpp"
#include "tests/support/Cli.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;
using nlohmann::json;
using ::testing::HasSubstr;

namespace {

json point(double solidFraction, double restitution, double pressure) {
  return {{"family", "simple_shear"},   {"solid_fraction", solidFraction},
          {"restitution", restitution}, {"diameter", 1e-3},
          {"density", 2500.0},          {"frames", 10},
          {"pressure", pressure},       {"pressure_err", 0.5}};
}

// A database with one run per entry of `runs` (keys key-one, key-two, ...), each holding its points.
std::filesystem::path closureDatabase(const TempDir& dir, const std::vector<json>& runs) {
  const auto path = dir.path() / "gb.sqlite";
  auto database = db::Database::open(path);
  database.transaction([&](db::Database& d) {
    db::ProvenanceStore provenance(d);
    const auto invocation = provenance.insertInvocation(db::test::sampleInvocation());
    const char* keys[] = {"key-one", "key-two", "key-three"};
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const auto run = provenance.insertRun(db::test::sampleRun(invocation, keys[k]));
      db::ClosureStore(d).insertRecords(run, {{"closure_points", runs[k]}});
    }
  });
  return path;
}

// Two runs: points at solid fraction 0.1, 0.2 (e 0.9) and 0.3 (e 0.7).
std::filesystem::path closureDatabase(const TempDir& dir) {
  return closureDatabase(dir, {json::array({point(0.1, 0.9, 10.0), point(0.2, 0.9, 20.0)}),
                               json::array({point(0.3, 0.7, 30.0)})});
}

}  // namespace

TEST(DbQueryCli, FiltersByStateRangeAndPrintsCsv) {
  TempDir dir;
  const auto path = closureDatabase(dir);
  const auto r = runGrainbridge(dir.path(), "db query --db '" + path.string() +
                                                "' --where solid_fraction=0.15:0.35 --columns "
                                                "solid_fraction,restitution,pressure,run_key --format csv");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output, "solid_fraction,restitution,pressure,run_key\n0.2,0.9,20,key-one\n0.3,0.7,30,key-two\n");
}

TEST(DbQueryCli, ExactValuesRunsAndJson) {
  TempDir dir;
  const auto path = closureDatabase(dir);
  const auto r = runGrainbridge(
      dir.path(), "db query --db '" + path.string() + "' --where restitution=0.9 --where pressure=15: --format json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto rows = json::parse(r.output);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_DOUBLE_EQ(rows[0]["solid_fraction"].get<double>(), 0.2);
  EXPECT_EQ(rows[0]["family"], "simple_shear");
  const auto table = runGrainbridge(dir.path(), "db query --db '" + path.string() + "' --run 2");
  ASSERT_EQ(table.exitCode, 0) << table.output;
  EXPECT_THAT(table.output, HasSubstr("(1 row)"));
  EXPECT_THAT(table.output, HasSubstr("key-two"));
}

TEST(DbQueryCli, UnknownColumnsAreAUsageErrorListingTheColumns) {
  TempDir dir;
  const auto path = closureDatabase(dir);
  auto r = runGrainbridge(dir.path(), "db query --db '" + path.string() + "' --where phi=0.1:0.2");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.output, HasSubstr("--where: no column \"phi\" in closure_points"));
  EXPECT_THAT(r.output, HasSubstr("columns: id, run_id, family"));
  r = runGrainbridge(dir.path(), "db query --db '" + path.string() + "' --where solid_fraction=a:0.2");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.output, HasSubstr("\"a\" is not a number"));
  r = runGrainbridge(dir.path(), "db query --db '" + path.string() + "' --columns pressure,presure");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.output, HasSubstr("--columns: no column \"presure\" in closure_points (did you mean \"pressure\"?)"));
  r = runGrainbridge(dir.path(), "db query --db '" + path.string() + "' --where restitutio=0.9");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.output, HasSubstr("(did you mean \"restitution\"?)"));
}

// A mixture's points carry their species (issue 60): `--where species=small` is text equality, and
// text against a number column is refused, not an empty answer.
TEST(DbQueryCli, ATextColumnMatchesItsText) {
  TempDir dir;
  json small = point(0.1, 0.9, 10.0), large = point(0.1, 0.9, 12.0), pair = point(0.2, 0.9, 3.0);
  small["species"] = "small";
  large["species"] = "large";
  pair["species"] = "small+large";
  const auto path = closureDatabase(dir, {json::array({point(0.2, 0.9, 20.0), small, large, pair})});
  const auto r = runGrainbridge(dir.path(), "db query --db '" + path.string() +
                                                "' --where species=small --columns species,pressure --format csv");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output, "species,pressure\nsmall,10\n");
  const auto both = runGrainbridge(dir.path(), "db query --db '" + path.string() +
                                                   "' --where species=small+large --where solid_fraction=0.2 "
                                                   "--columns species,pressure --format csv");
  ASSERT_EQ(both.exitCode, 0) << both.output;
  EXPECT_EQ(both.output, "species,pressure\nsmall+large,3\n");
  const auto wrong = runGrainbridge(dir.path(), "db query --db '" + path.string() + "' --where restitution=high");
  EXPECT_NE(wrong.exitCode, 0);
  EXPECT_THAT(wrong.output, HasSubstr("\"high\" is not a number, and closure_points.restitution is a number column"));
}

// A closure point stores the state measured in its run (the quickstart's phi 0.3 box holds
// 0.300004), and a user selects it by the value the config and the report name (issue 54).
TEST(DbQueryCli, MeasuredStatesMatchTheRoundValueWritten) {
  TempDir dir;
  const auto path = closureDatabase(
      dir, {json::array({point(0.0999998, 0.9, 10.0), point(0.2, 0.9, 20.0), point(0.300004, 0.9, 30.0)})});
  auto rows = [&](const std::string& where) {
    const auto r = runGrainbridge(dir.path(), "db query --db '" + path.string() + "' " + where + " --format json");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return json::parse(r.output.substr(r.output.find('['))).size();
  };
  EXPECT_EQ(rows("--where solid_fraction=0.1:0.3"), 3u);
  EXPECT_EQ(rows("--where solid_fraction=0.3"), 1u);
  EXPECT_EQ(rows("--where solid_fraction=0.1"), 1u);
  EXPECT_EQ(rows("--where solid_fraction=0.2:"), 2u);
  // 0.1 % of the value written, no more: 0.301 is another state.
  EXPECT_EQ(rows("--where solid_fraction=0.301"), 0u);
  // No match says what the column holds.
  const auto miss = runGrainbridge(dir.path(), "db query --db '" + path.string() + "' --where solid_fraction=0.35");
  EXPECT_EQ(miss.exitCode, 0) << miss.output;
  EXPECT_THAT(miss.output, HasSubstr("no row matches --where"));
  EXPECT_THAT(miss.output, HasSubstr("solid_fraction has 0.0999998 0.2 0.300004"));
}

TEST(DbQueryCli, ExportWritesEveryTableAsJsonOrCsv) {
  TempDir dir;
  const auto path = closureDatabase(dir);
  auto r = runGrainbridge(dir.path(), "db export --db '" + path.string() + "' -o all.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto all = json::parse(readText(dir.path() / "all.json"));
  EXPECT_EQ(all["closure_points"].size(), 3u);
  EXPECT_EQ(all["runs"].size(), 2u);
  EXPECT_EQ(all["runs"][0]["key"], "key-one");
  r = runGrainbridge(dir.path(), "db export --db '" + path.string() + "' -o folder");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string csv = readText(dir.path() / "folder/closure_points.csv");
  EXPECT_THAT(csv, HasSubstr("id,run_id,family,species,solid_fraction"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
}

// Issue 31: a closure table's nodes with their standard errors, one row per node, filtered by
// state range like the points; a table without errors shows none.
TEST(DbQueryCli, ClosureTablesShowEachNodeWithItsStandardError) {
  TempDir dir;
  const auto path = closureDatabase(dir);
  {
    auto database = db::Database::open(path);
    database.transaction([&](db::Database& d) {
      db::ProvenanceStore provenance(d);
      const auto invocation = provenance.insertInvocation(db::test::sampleInvocation());
      const auto run = provenance.insertRun(db::test::sampleRun(invocation, "key-table"));
      const json withErrors = {{"name", "shear"},
                               {"quantity", "p_theta"},
                               {"second_variable", "restitution"},
                               {"solid_fractions", {0.1, 0.2}},
                               {"seconds", {0.7, 0.9}},
                               {"values", {1.0, 2.0, 1.5, 2.5}},
                               {"uncertainties", {0.1, 0.2, 0.15, 0.25}}};
      json without = withErrors;
      without["quantity"] = "j_theta";
      without["uncertainties"] = json::array();
      db::ClosureStore(d).insertRecords(run, {{"closure_tables", {withErrors, without}}});
    });
  }
  const auto r = runGrainbridge(dir.path(), "db query --db '" + path.string() +
                                                "' --table closure_tables --where solid_fraction=0.2 --columns "
                                                "name,quantity,solid_fraction,second,value,uncertainty,run_key "
                                                "--format csv");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output,
            "name,quantity,solid_fraction,second,value,uncertainty,run_key\n"
            "shear,p_theta,0.2,0.7,2,0.2,key-table\n"
            "shear,p_theta,0.2,0.9,2.5,0.25,key-table\n"
            "shear,j_theta,0.2,0.7,2,,key-table\n"
            "shear,j_theta,0.2,0.9,2.5,,key-table\n");
  const auto bad = runGrainbridge(dir.path(), "db query --db '" + path.string() +
                                                  "' --table closure_tables --where pressure=1:2");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_THAT(bad.output, HasSubstr("no column \"pressure\" in closure table nodes"));
}
