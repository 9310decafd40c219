// Every workflow shipped in configs/ is valid, and the Brazil-nut smoke workflow (the CI-sized
// version of configs/bnp-wall-friction.json: 600 + 1 particles, 2 cycles) runs end to end with
// its two-step preparation, both wall frictions, the extraction (forces, structure, the nut
// against the local free surface) and the report.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "tests/support/Cli.hpp"
#include "tests/support/SharedInputs.hpp"

namespace fs = std::filesystem;
using namespace grainbridge::testing;

TEST(ShippedConfigs, AllPassCheck) {
  int checked = 0;
  for (const auto& e : fs::directory_iterator(sourceDir() / "configs")) {
    if (e.path().extension() != ".json") continue;
    if (needsMissingSharedInputs(sourceDir(), e.path())) continue;
    // From the repository root, as a user runs them (input files such as the LAMMPS chute
    // bed are given relative to it). check writes nothing.
    const auto r = runGrainbridge(sourceDir(), "check 'configs/" + e.path().filename().string() + "'");
    EXPECT_EQ(r.exitCode, 0) << e.path() << "\n" << r.output;
    ++checked;
  }
  EXPECT_GE(checked, 4);
}

TEST(BrazilNutSmoke, RunsWithPreparationAndWallFrictionSweep) {
  TempDir work;
  fs::copy_file(sourceDir() / "configs/bnp-smoke.json", work.path() / "bnp-smoke.json");
  const auto r = runGrainbridge(work.path(), "run bnp-smoke.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("preparation: relaxing"), std::string::npos) << r.output;
  int instances = 0;
  for (const auto& e : fs::directory_iterator(work.path() / "results/bnp-smoke/pack")) {
    ++instances;
    std::ifstream series(e.path() / "series.csv");
    std::string header;
    std::getline(series, header);
    EXPECT_NE(header.find("com_z_large"), std::string::npos) << header;
    EXPECT_NE(header.find("top_z_small"), std::string::npos) << header;
    EXPECT_NE(header.find("coordination"), std::string::npos) << header;
    int rows = 0;
    std::string line;
    while (std::getline(series, line)) ++rows;
    EXPECT_EQ(rows, 200);  // series_points = 100 per cycle
    EXPECT_TRUE(fs::exists(e.path() / "particles.xmf"));
    EXPECT_FALSE(fs::exists(e.path() / "checkpoint"));  // removed once complete
  }
  EXPECT_EQ(instances, 2);  // wall friction 0.5 and 0
  EXPECT_TRUE(fs::exists(work.path() / "results/bnp-smoke/summary"));

  // The extraction on the smoke frames: force PDFs (a fit the few forces cannot constrain is
  // recorded with its reason), force networks and five MST passes per frame, one closure point
  // per instance, all in the closure database.
  auto database = grainbridge::db::Database::openReadOnly(work.path() / "results/bnp-smoke/grainbridge.sqlite");
  grainbridge::db::ClosureStore store(database);
  grainbridge::db::ClosureQuery q;
  q.family = "bnp";
  EXPECT_EQ(store.query(q).size(), 2u);
  q.table = "force_statistics";
  const auto forces = store.query(q);
  // Eqs. 6.11 and 6.13 for each wall friction, over all contacts and over the contacts each of
  // the five MST passes found (Figs. 6.14-6.15).
  std::map<std::string, std::multiset<long>> countsBySource;  // "contacts", "mst_pass1".."mst_pass5"
  int contactRows = 0, mstRows = 0, contactFits = 0;
  for (const auto& row : forces) {
    EXPECT_TRUE(row["a"].is_number() || row["extra_json"].get<std::string>().find("fit_error") != std::string::npos)
        << row.dump();
    const std::string source = row["source"];
    countsBySource[source].insert(row["forces"].get<long>());
    if (source == "contacts") {
      ++contactRows;
      // The report has a row for each Eq. 6.11 fit (not Eq. 6.13's) that succeeded.
      contactFits += row["a"].is_number() && row["model"] == "eq6.11" ? 1 : 0;
    } else {
      EXPECT_EQ(source.rfind("mst_pass", 0), 0u) << source;
      ++mstRows;
    }
  }
  EXPECT_EQ(contactRows, 4);
  EXPECT_EQ(mstRows, 5 * 4);
  // Each MST pass adds contacts to the ones before it, and all of them are among the repulsive
  // contacts (per frame: the sorted counts compare frame by frame, the frames' sizes differ).
  auto atMost = [](const std::multiset<long>& a, const std::multiset<long>& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](long x, long y) { return x <= y; });
  };
  for (int pass = 1; pass < 5; ++pass) {
    EXPECT_TRUE(atMost(countsBySource["mst_pass" + std::to_string(pass)],
                       countsBySource["mst_pass" + std::to_string(pass + 1)]))
        << "pass " << pass;
  }
  EXPECT_TRUE(atMost(countsBySource["mst_pass5"], countsBySource["contacts"]));
  q.table = "structure_statistics";
  const auto structure = store.query(q);
  EXPECT_GT(structure.size(), 0u);
  int mstPasses = 0;
  for (const auto& row : structure) {
    mstPasses += row["kind"] == "mst" ? 1 : 0;
    if (row["kind"] != "force_networks" || !row["largest_extent"].is_number()) continue;
    // the extent in d0 as the reference gives it (52.2 d0): the small grains are 1 d0 here
    const auto extra = nlohmann::json::parse(row["extra_json"].get<std::string>());
    EXPECT_DOUBLE_EQ(extra.at("largest_extent_diameters").get<double>() * extra.at("smallest_diameter").get<double>(),
                     row["largest_extent"].get<double>());
  }
  EXPECT_EQ(mstPasses % 5, 0);

  // The validation report gathers the Brazil-nut figures from the database: the Eq. 6.11 fit of
  // all contacts (not of the MST passes' contacts), the networks and the Table 6.2 fractions.
  const auto report =
      runGrainbridge(work.path(), "report validation --db results/bnp-smoke/grainbridge.sqlite -o v.html");
  EXPECT_EQ(report.exitCode, 0) << report.output;
  std::ifstream html(work.path() / "v.html");
  const std::string page((std::istreambuf_iterator<char>(html)), std::istreambuf_iterator<char>());
  for (const char* check :
       {"Eq. 6.11 fit to the Brazil-nut contact forces: a (", "particles in the largest network",
        "after 1 MST pass(es)", "after 5 MST pass(es)", "extent of the largest network [d0, the smallest diameter]",
        // each row names the state of its run: the two wall frictions of the sweep
        ": pack, seed 1, side-wall friction 0.5)", ": pack, seed 1, side-wall friction 0)"}) {
    EXPECT_NE(page.find(check), std::string::npos) << check;
  }
  int forcePdfRows = 0;
  const std::string fit = "Eq. 6.11 fit to the Brazil-nut contact forces: a (";
  for (auto at = page.find(fit); at != std::string::npos; at = page.find(fit, at + 1)) ++forcePdfRows;
  // One row per Eq. 6.11 fit of all contacts that succeeded; the MST passes' fits are not rows.
  EXPECT_EQ(forcePdfRows, contactFits);
  EXPECT_GE(forcePdfRows, 1);

  // The nut against the local free surface: one row per frame in surface.csv, its verdict in
  // the manifest summary, and no closure point (closure_point: false; the 2 above are forces').
  int surfaces = 0;
  for (const auto& e : fs::directory_iterator(work.path() / "results/bnp-smoke/surface")) {
    ++surfaces;
    std::ifstream csv(e.path() / "surface.csv");
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header.rfind("time,step,id,top,surface,gap,gap_diameters", 0), 0u) << header;
    int rows = 0;
    while (std::getline(csv, line)) {
      ++rows;
      std::vector<std::string> fields;
      std::stringstream row(line);
      for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
      ASSERT_GE(fields.size(), 3u) << line;
      EXPECT_EQ(fields[2], "0") << "the id column names the nut: " << line;
    }
    EXPECT_EQ(rows, 5);  // 4 frames + the initial one
    EXPECT_FALSE(fs::exists(e.path() / "closure_point.csv"));
    std::ifstream manifest(e.path() / "manifest.json");
    const auto summary = nlohmann::json::parse(manifest).at("summary");
    EXPECT_TRUE(summary.contains("surface_id0_settled_at_top_time")) << summary.dump();
    EXPECT_TRUE(summary.at("surface_id0_judged_frames").is_number()) << summary.dump();
  }
  EXPECT_EQ(surfaces, 2);
}
