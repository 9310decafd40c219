// force_statistics on frames with no contact: a dilute gas (the solid fraction 0.05 states of
// configs/shear-closures.json go 400 frames without one) still gets its closure point and its
// velocity statistics; the missing force PDF is explained, not a failed run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "tests/support/Cli.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;
using nlohmann::json;
namespace fs = std::filesystem;

TEST(ExtractForceStatistics, AFrameWithoutContactsGivesVelocityStatisticsAndSaysWhyThereIsNoForcePdf) {
  TempDir work;
  // Random non-overlapping spheres: one frame, no contact at all.
  const json gas = {{"type", "particle_gas"},
                    {"params", {{"n_particles", 400}, {"solid_fraction", 0.05}, {"progress", false}}}};
  const json x = {{"type", "extract"},
                  {"from", "gas"},
                  {"params", {{"family", "dilute"}, {"force_statistics", true}, {"correlation_range", 3}}}};
  writeText(work.path() / "wf.json", json{{"name", "dilute"}, {"stages", {{"gas", gas}, {"x", x}}}}.dump(2));
  const auto r = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("no force PDF or force correlation"), std::string::npos) << r.output;

  fs::path dir;
  for (const auto& e : fs::directory_iterator(work.path() / "results/dilute/x")) dir = e.path();
  EXPECT_FALSE(fs::exists(dir / "force_pdf.csv"));
  ASSERT_TRUE(fs::exists(dir / "correlations.csv"));
  std::ifstream csv(dir / "correlations.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "r,force_pairs,force_correlation,force_correlation_err,velocity_correlation,velocity_correlation_err");
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    EXPECT_NE(line.find(",0,nan,nan,"), std::string::npos) << "no force pairs, no force correlation: " << line;
  }
  EXPECT_GT(rows, 0);

  auto database = db::Database::openReadOnly(work.path() / "results/dilute/grainbridge.sqlite");
  db::ClosureStore store(database);
  db::ClosureQuery q;
  q.family = "dilute";
  const auto points = store.query(q);
  ASSERT_EQ(points.size(), 1u);
  const auto extra = json::parse(points[0]["extra_json"].get<std::string>());
  EXPECT_NE(extra.value("force_statistics_skipped", "").find("none of the 1 averaged frames"), std::string::npos)
      << extra.dump();
  ASSERT_TRUE(extra.contains("velocity_kurtosis")) << extra.dump();
  // 400 Maxwellian velocities: each component's kurtosis is near the Maxwellian 3.
  for (const auto& k : extra["velocity_kurtosis"]) EXPECT_NEAR(k.get<double>(), 3.0, 1.0);
  q.table = "force_statistics";
  EXPECT_TRUE(store.query(q).empty());
}
