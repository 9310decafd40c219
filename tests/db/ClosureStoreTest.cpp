// The closure database: rows a stage reports are inserted against the schema's own columns,
// queried by family, state range and run, and closure tables load into core::ClosureTable.
// Two processes writing closure points at once lose nothing.
#include "db/ClosureStore.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <optional>

#include <sys/wait.h>
#include <unistd.h>

#include "core/Error.hpp"
#include "db/Database.hpp"
#include "db/ProvenanceStore.hpp"
#include "tests/db/TestSupport.hpp"

namespace grainbridge::db {
namespace {

using nlohmann::json;
using test::countRows;
using test::sampleInvocation;
using test::sampleRun;
using test::TempDir;
using ::testing::HasSubstr;

json point(double solidFraction, double restitution, double pressure) {
  return {{"family", "simple_shear"},
          {"solid_fraction", solidFraction},
          {"restitution", restitution},
          {"friction", 0.0},
          {"shear_rate", 1.0},
          {"diameter", 1e-3},
          {"density", 2500.0},
          {"frames", 20},
          {"pressure", pressure},
          {"pressure_err", 0.01 * pressure},
          {"extra_json", {{"note", "test"}}}};
}

std::int64_t newRun(Database& db, const std::string& key) {
  return db.transaction([&](Database& d) {
    ProvenanceStore store(d);
    const auto invocation = store.insertInvocation(sampleInvocation());
    return store.insertRun(sampleRun(invocation, key));
  });
}

ClosureQuery withRanges(std::vector<ColumnRange> ranges, std::string table = "closure_points") {
  ClosureQuery q;
  q.table = std::move(table);
  q.ranges = std::move(ranges);
  return q;
}

std::string errorOf(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(ClosureStore, InsertsReportedRowsAndQueriesThemByFamilyRangeAndRun) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  const auto run1 = newRun(db, "k1");
  const auto run2 = newRun(db, "k2");
  db.transaction([&](Database& d) {
    ClosureStore store(d);
    store.insertRecords(run1, {{"closure_points", {point(0.1, 0.9, 10.0), point(0.3, 0.9, 50.0)}}});
    store.insertRecords(
        run2, {{"closure_points", {point(0.2, 0.7, 20.0)}},
               {"force_statistics",
                {{{"family", "bnp"}, {"source", "contacts"}, {"forces", 1000}, {"model", "eq6.11"}, {"a", 2.4}}}}});
  });
  ClosureStore store(db);
  EXPECT_EQ(store.query({}).size(), 3u);
  const auto dense = store.query(withRanges({{"solid_fraction", 0.15, std::nullopt}}));
  ASSERT_EQ(dense.size(), 2u);
  EXPECT_DOUBLE_EQ(dense[0]["solid_fraction"].get<double>(), 0.3);
  EXPECT_EQ(dense[0]["run_key"], "k1");  // the provenance link travels with the row
  EXPECT_EQ(dense[1]["run_id"], run2);
  EXPECT_EQ(store.query(withRanges({{"restitution", 0.8, 1.0}, {"solid_fraction", 0.0, 0.2}})).size(), 1u);
  ClosureQuery ofRun;
  ofRun.runId = run2;
  EXPECT_EQ(store.query(ofRun).size(), 1u);
  ClosureQuery ofFamily;
  ofFamily.family = "fluidized_cell";
  EXPECT_EQ(store.query(ofFamily).size(), 0u);
  EXPECT_EQ(json::parse(store.query({})[0]["extra_json"].get<std::string>())["note"], "test");
  const auto forces = store.query(withRanges({}, "force_statistics"));
  ASSERT_EQ(forces.size(), 1u);
  EXPECT_EQ(forces[0]["forces"], 1000);
}

TEST(ClosureStore, RefusesUnknownTablesAndColumnsNamingThem) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  const auto run = newRun(db, "k1");
  ClosureStore store(db);
  json bad = point(0.1, 0.9, 1.0);
  bad["presure"] = 3.0;
  EXPECT_THAT(errorOf([&] {
                store.insertRecords(run, {{"closure_points", {point(0.2, 0.9, 1.0), bad}}});
              }),
              HasSubstr("records/closure_points/1: no column \"presure\" in closure_points"));
  EXPECT_THAT(errorOf([&] {
                store.insertRecords(run, {{"closure_pionts", json::array()}});
              }),
              HasSubstr("no table \"closure_pionts\""));
  EXPECT_THAT(errorOf([&] { store.query(withRanges({{"phi", 0.1, 0.2}})); }), HasSubstr("no column \"phi\""));
  // A schema CHECK holds too: a solid fraction of 1.2 is no state.
  EXPECT_THROW(store.insertRecords(run, {{"closure_points", {point(1.2, 0.9, 1.0)}}}), Error);
}

TEST(ClosureStore, AClosureTableLoadsIntoCoreClosureTableNewestFirst) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  const auto older = newRun(db, "k1");
  const auto newer = newRun(db, "k2");
  const json table = {{"name", "shear"},
                      {"quantity", "p_theta"},
                      {"second_variable", "restitution"},
                      {"solid_fractions", {0.1, 0.2, 0.3}},
                      {"seconds", {0.7, 0.9}},
                      {"values", {1.0, 2.0, 3.0, 1.5, 2.5, 3.5}},
                      {"uncertainties", {0.1, 0.1, 0.1, 0.1, 0.1, 0.1}}};
  json newerTable = table;
  newerTable["values"] = {2.0, 4.0, 6.0, 3.0, 5.0, 7.0};
  db.transaction([&](Database& d) {
    ClosureStore(d).insertRecords(newer, {{"closure_tables", {newerTable}}});
    ClosureStore(d).insertRecords(older, {{"closure_tables", {table}}});
  });
  ClosureStore store(db);
  const auto loaded = store.loadTable("shear", "p_theta");
  EXPECT_TRUE(loaded.table.twoDimensional());
  EXPECT_EQ(loaded.table.secondVariable(), "restitution");
  EXPECT_DOUBLE_EQ(loaded.table(0.2, 0.8).value, 4.5);  // the newer run's table, halfway between 4 and 5
  EXPECT_EQ(loaded.name, "shear");
  EXPECT_EQ(loaded.runKey, "k2");
  EXPECT_EQ(loaded.sha256, core::contentSha256(loaded.table));
  // The nodes' standard errors come along (issue 31), and through the instance task's JSON.
  EXPECT_EQ(loaded.uncertainties, std::vector<double>(6, 0.1));
  EXPECT_EQ(core::loadedClosureTableFromJson(json(loaded)).uncertainties, loaded.uncertainties);
  // A run key selects that run's table (one made upstream in the same workflow), whatever is newer.
  const auto fromOlder = store.loadTable("shear", "p_theta", "k1");
  EXPECT_EQ(fromOlder.runKey, "k1");
  EXPECT_DOUBLE_EQ(fromOlder.table(0.2, 0.8).value, 2.25);
  // The hash is over the content: the two runs' tables differ, so do their hashes.
  EXPECT_NE(fromOlder.sha256, loaded.sha256);
  EXPECT_THAT(errorOf([&] { store.loadTable("shear", "p_theta", "k3"); }), HasSubstr("from run k3"));
  EXPECT_THAT(errorOf([&] { store.loadTable("shear", "eta_theta"); }),
              HasSubstr("no closure table \"shear\" of quantity \"eta_theta\" (tables: shear/p_theta)"));
  json malformed = table;
  malformed["values"] = {1.0, 2.0};
  EXPECT_THAT(errorOf([&] {
                store.insertRecords(newer, {{"closure_tables", {malformed}}});
              }),
              HasSubstr("2 values for a 3 x 2 grid"));
}

// A mixture species' table of three axes (issue 60) is stored with its third and comes back
// whole; its nodes name their third value.
TEST(ClosureStore, ATableOfThreeAxesKeepsItsThirdAxis) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  const auto run = newRun(db, "k1");
  std::vector<double> values;
  for (int k = 0; k < 2 * 2 * 3; ++k) values.push_back(1.0 + k);
  const json table = {{"name", "pair_small"},
                      {"quantity", "p_theta"},
                      {"second_variable", "volume_share"},
                      {"solid_fractions", {0.1, 0.2, 0.3}},
                      {"seconds", {0.25, 0.75}},
                      {"third_variable", "restitution"},
                      {"thirds", {0.9, 0.97}},
                      {"values", values},
                      {"uncertainties", std::vector<double>(12, 0.1)}};
  db.transaction([&](Database& d) { ClosureStore(d).insertRecords(run, {{"closure_tables", {table}}}); });
  ClosureStore store(db);
  const auto loaded = store.loadTable("pair_small", "p_theta");
  ASSERT_TRUE(loaded.table.threeDimensional());
  EXPECT_EQ(loaded.table.thirdVariable(), "restitution");
  EXPECT_EQ(loaded.table.thirds(), (std::vector<double>{0.9, 0.97}));
  // values[(iz * 2 + iy) * 3 + ix]: (0.2, 0.75, 0.97) is node (1, 1, 1), value 1 + 10.
  EXPECT_DOUBLE_EQ(loaded.table(0.2, 0.75, 0.97).value, 11.0);
  const auto nodes = store.tableNodes({});
  ASSERT_EQ(nodes.size(), 12u);
  EXPECT_EQ(nodes[10]["third_variable"], "restitution");
  EXPECT_DOUBLE_EQ(nodes[10]["third"].get<double>(), 0.97);
  EXPECT_DOUBLE_EQ(nodes[10]["second"].get<double>(), 0.75);
  EXPECT_DOUBLE_EQ(nodes[10]["solid_fraction"].get<double>(), 0.2);
  EXPECT_DOUBLE_EQ(nodes[10]["value"].get<double>(), 11.0);
  json malformed = table;
  malformed["values"] = std::vector<double>(6, 1.0);
  EXPECT_THAT(errorOf([&] { store.insertRecords(run, {{"closure_tables", {malformed}}}); }),
              HasSubstr("6 values for a 3 x 2 x 2 grid"));
}

json rheologyRow(std::optional<double> restitution, double muS) {
  json row = {{"name", "dense"},
              {"family", "simple_shear"},
              {"relation", "mu_of_I"},
              {"form", "mu_s + (mu_2 - mu_s) / (1 + I_0 / I)"},
              {"restitution", restitution ? json(*restitution) : json()},
              {"diameter", 1.5e-3},
              {"density", 2526.0},
              {"points", 2},
              {"inertial_numbers_json", {0.01, 0.1}},
              {"inertial_number_errors_json", {0.001, 0.01}},
              {"values_json", {muS, muS + 0.1}},
              {"uncertainties_json", {0.01, 0.01}}};
  if (restitution && *restitution > 0.8) {
    row["mu_s"] = muS;
    row["mu_2"] = 0.64;
    row["inertial_number_0"] = 0.28;
  }
  return row;
}

TEST(ClosureStore, ARheologyLoadsItsMuOfIRowsWithTheirGrainsNewestFirst) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  const auto older = newRun(db, "k1");
  const auto newer = newRun(db, "k2");
  json phi = rheologyRow(0.9, 0.6);
  phi["relation"] = "phi_of_I";
  db.transaction([&](Database& d) {
    ClosureStore(d).insertRecords(older, {{"rheology", {rheologyRow(0.9, 0.30)}}});
    ClosureStore(d).insertRecords(newer, {{"rheology", {rheologyRow(0.9, 0.35), rheologyRow(0.7, 0.33), phi}}});
  });
  ClosureStore store(db);
  const auto loaded = store.loadRheology("dense");
  EXPECT_EQ(loaded.runKey, "k2");
  EXPECT_EQ(loaded.diameter, 1.5e-3);
  EXPECT_EQ(loaded.density, 2526.0);
  ASSERT_EQ(loaded.rows.size(), 2u);  // mu(I) only, in increasing restitution
  EXPECT_EQ(loaded.rows[0].restitution, 0.7);
  EXPECT_FALSE(loaded.rows[0].fit.has_value());
  const auto* e09 = loaded.atRestitution(0.9);
  ASSERT_NE(e09, nullptr);
  ASSERT_TRUE(e09->fit.has_value());
  EXPECT_EQ(e09->fit->staticRatio, 0.35);
  EXPECT_EQ(e09->stressRatios, (std::vector<double>{0.35, 0.35 + 0.1}));  // as stored
  EXPECT_EQ(loaded.atRestitution(0.8), nullptr);
  EXPECT_EQ(loaded.sha256, core::contentSha256(loaded));
  // The record round-trips through the instance task's JSON, hash and all.
  const auto back = core::loadedRheologyFromJson(json(loaded));
  EXPECT_EQ(core::contentSha256(back), loaded.sha256);
  EXPECT_EQ(back.rows[1].fit->inertialNumberScale, 0.28);
  // A run key selects that run's rows; the content hash tells them apart.
  const auto fromOlder = store.loadRheology("dense", "k1");
  ASSERT_EQ(fromOlder.rows.size(), 1u);
  EXPECT_NE(fromOlder.sha256, loaded.sha256);
  EXPECT_THAT(errorOf([&] { store.loadRheology("loose"); }),
              HasSubstr("no mu(I) rheology \"loose\" (rheologies: dense)"));
}

constexpr int kPointsPerWriter = 300;

int writePoints(const std::filesystem::path& path, int writer) {
  try {
    Database db = Database::open(path);
    const auto run = newRun(db, "writer" + std::to_string(writer));
    for (int i = 0; i < kPointsPerWriter; ++i) {
      db.transaction([&](Database& d) {
        ClosureStore(d).insertRecords(run, {{"closure_points", {point(0.001 * i, 0.9, 1.0 + writer)}}});
      });
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "writer %d: %s\n", writer, e.what());
    return 1;
  }
}

TEST(ClosureStore, TwoProcessesWritingClosurePointsAtOnceLoseNothing) {
  TempDir dir;
  const auto path = dir / "gb.sqlite";
  Database::open(path);  // created and migrated, then closed: no connection crosses fork()
  pid_t writers[2];
  for (int w = 0; w < 2; ++w) {
    writers[w] = ::fork();
    ASSERT_GE(writers[w], 0);
    if (writers[w] == 0) ::_exit(writePoints(path, w));
  }
  for (pid_t pid : writers) {
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "writer " << pid << " status " << status;
  }
  Database db = Database::open(path);
  EXPECT_EQ(countRows(db, "closure_points"), 2 * kPointsPerWriter);
  ClosureStore store(db);
  EXPECT_EQ(store.query(withRanges({{"pressure", 1.5, 2.5}})).size(), static_cast<std::size_t>(kPointsPerWriter));
  EXPECT_EQ(db.integrityCheck(), "ok");
}

}  // namespace
}  // namespace grainbridge::db
