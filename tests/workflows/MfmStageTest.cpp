// The `mfm` stage end to end (issue 17): the grain-fluidization smoke workflow writes what a
// user of MFiX expects to open (field frames for ParaView, the time-averaged fields, a series
// with the pressure drop and the bed height), its summary carries the time-averaged pressure
// drop with its block-averaging error, and a run that cannot continue stops naming the time,
// the cell and the quantity, with its last good frame on disk.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "core/io/FieldFrameReader.hpp"
#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "db/ProvenanceStore.hpp"
#include "tests/db/TestSupport.hpp"
#include "tests/support/Cli.hpp"
#include "tests/support/CsvLine.hpp"
#include "tests/support/TinyShear.hpp"
#include "tests/support/WorkflowResults.hpp"
#include "workflows/contract/NumericCsv.hpp"

namespace fs = std::filesystem;
using namespace grainbridge::testing;
using nlohmann::json;

TEST(MfmStage, GrainSmokeWritesFramesMeanFieldsSeriesAndAFluidizationCurve) {
  TempDir work;
  fs::copy_file(sourceDir() / "configs/grain-fluidization-smoke.json", work.path() / "smoke.json");
  const auto r = runGrainbridge(work.path(), "run smoke.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  int beds = 0;
  for (const auto& e : fs::directory_iterator(work.path() / "results/grain-fluidization-smoke/bed")) {
    const fs::path bed = e.path();
    ++beds;
    EXPECT_TRUE(fs::exists(bed / "fields.xmf"));
    EXPECT_TRUE(fs::exists(bed / "frames/fields_000000000.h5"));
    EXPECT_TRUE(fs::exists(bed / "mean/fields.xmf"));
    const std::string series = readText(bed / "series.csv");
    EXPECT_EQ(series.substr(0, series.find('\n')),
              "time,step,dp_bed,mean_height_grain,solids_volume_grain,dt,solver_steps,iterations,residual,"
              "plastic_solids_share,mass_gas,mass_in_gas,mass_out_gas,mass_out_gas_y_high,mass_grain,mass_in_grain,"
              "mass_out_grain,"
              "mass_out_grain_y_high");
    // A row every output_interval (0.01 s: the solver's adaptive steps land on each), and the
    // throughput counts the solver's steps, not the rows (issue 54).
    const auto columns = grainbridge::workflows::contract::readNumericCsv(bed / "series.csv");
    const auto& times = columns.at("time");
    for (std::size_t k = 0; k < times.size(); ++k)
      EXPECT_NEAR(times[k], 0.01 * static_cast<double>(k + 1), 1e-12) << "row " << k;
    const auto solverSteps = static_cast<std::int64_t>(columns.at("solver_steps").back());
    EXPECT_GT(solverSteps, static_cast<std::int64_t>(times.size()));
    EXPECT_NE(r.output.find(": " + std::to_string(solverSteps) + " solver steps of "), std::string::npos) << r.output;
    const json manifest = json::parse(readText(bed / "manifest.json"));
    const json summary = manifest.at("summary");
    // The curve's abscissa as a product of the run: the one bottom inlet of pure gas gives the
    // swept inflow bit for bit, so the curve is where the swept inflows put it.
    EXPECT_EQ(summary.at("superficial_gas_velocity").get<double>(),
              manifest.at("sweep_point").at("boundaries/0/gas_inflow").get<double>());
    // Short runs: a sanity bound on the drop (below the 664 Pa weight at low inflow, not far
    // above it at high), an error that is a number, and the inventory kept.
    EXPECT_GT(summary.at("dp_bed").get<double>(), 0.0);
    EXPECT_LT(summary.at("dp_bed").get<double>(), 1000.0);
    EXPECT_GE(summary.at("dp_bed_err").get<double>(), 0.0);
    EXPECT_LT(std::abs(summary.at("solids_volume_change").get<double>()), 1e-6);
    // The mass account: the gas flows through, the walled grains stay, each balance closes.
    EXPECT_GT(summary.at("mass_in_gas").get<double>(), 0.0);
    EXPECT_EQ(summary.at("mass_in_grain").get<double>(), 0.0);
    EXPECT_EQ(summary.at("mass_out_grain").get<double>(), 0.0);
    EXPECT_LT(std::abs(summary.at("mass_balance_grain").get<double>()), 1e-12);
    EXPECT_LT(std::abs(summary.at("mass_balance_gas").get<double>()), 1e-6);
    // What the curve is read against: the bed's buoyant weight (664 Pa at eps 0.404 less the
    // 2 % perturbation's share) and the drag law's U_mf (0.797 m/s for C 0.8, D 2.65).
    EXPECT_NEAR(summary.at("bed_weight").get<double>(), 664.0, 0.03 * 664.0);
    EXPECT_NEAR(summary.at("drag_umf").get<double>(), 0.797, 0.001);
  }
  EXPECT_EQ(beds, 5);
  // The fluidization stage read the five points as one curve and drew it.
  const fs::path fl = onlyInstance(work.path() / "results/grain-fluidization-smoke/fluidization");
  ASSERT_FALSE(fl.empty());
  const json manifest = json::parse(readText(fl / "manifest.json"));
  EXPECT_EQ(manifest.at("findings").at("rows").size(), 1u);
  EXPECT_NE(manifest.at("findings").at("headline").get<std::string>().find("bed weight"), std::string::npos);
  EXPECT_TRUE(fs::exists(fl / "fluidization.svg"));
  EXPECT_TRUE(fs::exists(fl / "fluidization.csv"));
}

TEST(MfmStage, DivergingRunNamesTimeCellAndQuantityAndKeepsTheLastGoodFrame) {
  TempDir work;
  json wf = json::parse(readText(sourceDir() / "configs/grain-fluidization-smoke.json"));
  wf["stages"].erase("report");
  wf["stages"].erase("fluidization");
  wf["stages"]["bed"].erase("sweep");
  auto& p = wf["stages"]["bed"]["params"];
  // A fixed step far too long for a packed bed (its Courant number is fine: 0.4 cells).
  p["dt"] = p["dt_min"] = p["dt_max"] = "8e-3 s";
  p["boundaries"][0]["gas_inflow"] = "0.5 m/s";
  writeText(work.path() / "div.json", wf.dump());
  const auto r = runGrainbridge(work.path(), "run div.json");
  EXPECT_NE(r.output.find("at t = 0 s no step down to the minimum"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("cell ("), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("frames up to step 0 are kept"), std::string::npos) << r.output;
  bool kept = false;
  for (const auto& e : fs::directory_iterator(work.path() / "results/grain-fluidization-smoke/bed")) {
    kept = kept || fs::exists(e.path() / "frames/fields_000000000.h5");
  }
  EXPECT_TRUE(kept);
}

TEST(MfmStage, GoldschmidtSmokeRunsKineticTheoryWithWallsWithAndWithoutRotation) {
  // configs/goldschmidt-mono-smoke.json: the Chapter 5 bed (Lun et al. with the granular-energy
  // equation, Johnson-Jackson walls) for 0.3 s, without and with the rotation model.
  TempDir work;
  fs::copy_file(sourceDir() / "configs/goldschmidt-mono-smoke.json", work.path() / "smoke.json");
  const auto r = runGrainbridge(work.path(), "run smoke.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  int beds = 0;
  for (const auto& e : fs::directory_iterator(work.path() / "results/goldschmidt-mono-smoke/bed")) {
    const fs::path bed = e.path();
    ++beds;
    const json manifest = json::parse(readText(bed / "manifest.json"));
    const json& summary = manifest.at("summary");
    // The 15 cm bed at solid fraction 0.583 starts with its mean particle height at 7.5 cm and
    // expands once the gas at 1.5 U_mf goes through it.
    EXPECT_GT(summary.at("mean_height").get<double>(), 0.075);
    EXPECT_LT(summary.at("mean_height").get<double>(), 0.2);
    // fraction_relaxation 1 withholds nothing: the inventory is kept to round-off.
    EXPECT_LT(std::abs(summary.at("solids_volume_change").get<double>()), 1e-12);
    // The bed's buoyant weight per unit area, (1 - eps) (rho_s - rho_g) g H (VALIDATION.md: about
    // 2166 Pa).
    EXPECT_NEAR(summary.at("bed_weight").get<double>(), 2166.0, 0.01 * 2166.0);
    EXPECT_TRUE(fs::exists(bed / "mean/fields.xmf"));
    // Never a solids fraction below zero beyond round-off (positivity-preserving faces and the
    // implicit continuity closing each step, engines/fluid).
    for (const auto& frame : fs::directory_iterator(bed / "frames")) {
      if (frame.path().extension() != ".h5") continue;
      for (double eps : grainbridge::core::io::readFieldFrame(frame.path()).solids.at(0).ep_s)
        ASSERT_GE(eps, -1e-12) << frame.path();
    }
  }
  EXPECT_EQ(beds, 2);

  // The heights stage (bed_compare) matched each run to its Table 5.3 value by the sweep's
  // rotation_model, and the experiment to both.
  std::map<std::string, double> heightOf;  // by rotation_model as written
  for (const auto& e : fs::directory_iterator(work.path() / "results/goldschmidt-mono-smoke/bed")) {
    const json manifest = json::parse(readText(e.path() / "manifest.json"));
    heightOf[manifest.at("sweep_point").at("rotation_model").dump()] =
        manifest.at("summary").at("mean_height").get<double>();
  }
  const fs::path heights = onlyInstance(work.path() / "results/goldschmidt-mono-smoke/heights");
  ASSERT_FALSE(heights.empty());
  const json findings = json::parse(readText(heights / "manifest.json")).at("findings");
  EXPECT_EQ(findings.at("rows").size(), 2u);
  for (const char* f : {"solid_fraction_maps.svg", "mean_height.svg", "pressure_drop.svg", "bed_compare.html"}) {
    EXPECT_TRUE(fs::exists(heights / f)) << f;
  }
  std::map<std::string, int> rowsPerReference;
  std::istringstream csv(readText(heights / "beds.csv"));
  std::string line;
  std::getline(csv, line);
  // Columns by name: beds.csv gains columns as the comparison grows (segregation_percentage).
  const auto header = splitCsvLine(line);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << name;
    return static_cast<std::size_t>(it - header.begin());
  };
  while (std::getline(csv, line)) {
    // "bed (rotation_model false)",lun1984,h,...,"Table 5.3 model",reference,0.0921,deviation
    const bool rotation = line.find("rotation_model true") != std::string::npos;
    const double h = heightOf.at(rotation ? "true" : "false");
    const auto fields = splitCsvLine(line);
    ASSERT_EQ(fields.size(), header.size()) << line;
    EXPECT_DOUBLE_EQ(std::stod(fields[column("mean_height")]), h);
    EXPECT_TRUE(fields[column("segregation_percentage")].empty()) << "a mono bed has no s_p: " << line;
    const double reference = std::stod(fields[column("reference_height")]);
    const std::string& label = fields[column("reference")];
    if (label == "Table 5.3 model") {
      EXPECT_EQ(reference, rotation ? 0.0973 : 0.0921) << line;
    } else {
      EXPECT_EQ(label, "experiment");
      EXPECT_EQ(reference, 0.1140) << line;
    }
    EXPECT_NEAR(std::stod(fields[column("deviation")]), (h - reference) / reference, 1e-12);
    ++rowsPerReference[label];
  }
  EXPECT_EQ(rowsPerReference["Table 5.3 model"], 2);
  EXPECT_EQ(rowsPerReference["experiment"], 2);
}

namespace {

// A loose grain bed (solids fraction 0.15) in the Chapter 5 model, 0.05 s: cells in the tiny
// shear table's range (solid fractions 0.097 and 0.168, e 0.9) and out of it.
json looseBed() {
  json wf = json::parse(readText(sourceDir() / "configs/grain-fluidization-smoke.json"));
  json bed = wf["stages"]["bed"];
  bed.erase("sweep");
  auto& p = bed["params"];
  p.erase("kinetic_model");
  p.erase("granular_energy");
  p["regions"][0]["solids_fractions"] = {0.15};
  p["boundaries"][0]["gas_inflow"] = "0.5 m/s";
  p["duration"] = "0.05 s";
  p["average_from"] = "0.02 s";
  p["frames"] = 1;
  p["closure"] = "table";
  p["closure_table"] = "t";
  p["out_of_range"] = "kinetic_theory";
  return bed;
}

json shearToTable() {
  json dem = tinyShearDemParams();
  dem.erase("box_hi");
  json stages = json::object();
  const json boxes = json::array({json::array({"6 mm", "6 mm", "6 mm"}), json::array({"5 mm", "5 mm", "5 mm"})});
  stages["shear"] = {{"type", "dem"}, {"params", dem}, {"sweep", {{"box_hi", boxes}}}};
  stages["points"] = {{"type", "extract"}, {"from", "shear"}, {"params", {{"family", "simple_shear"}}}};
  stages["table"] = {{"type", "tabulate"}, {"from", "points"}, {"params", {{"table", "t"}, {"second_variable", ""}}}};
  return stages;
}

}  // namespace

TEST(MfmStage, ReadsClosureTablesMadeUpstreamOrNamedInTheDatabaseAndCountsTheirCoverage) {
  TempDir work;
  // 1. DEM shear -> closure points -> table "t" -> the bed reading it through `from`.
  json stages = shearToTable();
  stages["bed"] = looseBed();
  stages["bed"]["from"] = "table";
  writeText(work.path() / "loop.json", json{{"name", "loop"}, {"stages", stages}}.dump(2));
  const auto r = runGrainbridge(work.path(), "run loop.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const fs::path bedDir = onlyInstance(work.path() / "results/loop/bed");
  const json summary = json::parse(readText(bedDir / "manifest.json")).at("summary");
  auto database = grainbridge::db::Database::openReadOnly(work.path() / "results/loop/grainbridge.sqlite");
  grainbridge::db::ClosureStore store(database);
  for (const char* q : {"p_theta", "eta_theta", "j_theta"}) {
    EXPECT_EQ(summary.at(std::string("table_sha256_") + q), store.loadTable("t", q).sha256) << q;
  }
  const double cells = summary.at("table_coverage_cell_steps"), solids = summary.at("table_coverage_solids");
  EXPECT_GT(summary.at("table_cell_steps").get<double>(), 0.0);
  EXPECT_GE(cells, 0.0);
  EXPECT_LE(cells, 1.0);
  EXPECT_GE(solids, 0.0);
  EXPECT_LE(solids, 1.0);

  // 2. Another workflow names the same table, without `from`: planned from the database, and its
  //    key carries the table's content hash; a table the database lacks is refused at check.
  json named = looseBed();
  const std::string dbPath = (work.path() / "results/loop/grainbridge.sqlite").string();
  writeText(work.path() / "named.json",
            json{{"name", "named"}, {"database", dbPath}, {"stages", {{"bed", named}}}}.dump(2));
  const auto ok = runGrainbridge(work.path(), "check named.json");
  EXPECT_EQ(ok.exitCode, 0) << ok.output;
  named["params"]["closure_table"] = "missing";
  writeText(work.path() / "missing.json",
            json{{"name", "named"}, {"database", dbPath}, {"stages", {{"bed", named}}}}.dump(2));
  const auto bad = runGrainbridge(work.path(), "check missing.json");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("/stages/bed/params/closure_table"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("\"missing\""), std::string::npos) << bad.output;
}

namespace {

// The loose bed on the tiny shear's grains (1 mm, 2500 kg/m3), packed past the plastic onset at
// the bottom (eps_s 0.60 > 1 - eps_g* = 0.596) and sheared by its walls as it settles, with the
// plastic viscosity of the tiny shear's mu(I) points.
json muOfIBed(const std::string& diameter) {
  json bed = looseBed();
  auto& p = bed["params"];
  p["solids"][0]["diameter"] = diameter;
  p["solids"][0]["density"] = "2500 kg/m3";
  p["closure"] = "ktgf";
  p.erase("closure_table");
  p.erase("out_of_range");
  p["packed_solids_fraction"] = 0.62;
  p["regions"][0]["solids_fractions"] = {0.60};
  p["boundaries"][0]["gas_inflow"] = "1 cm/s";
  p["plastic"] = "mu_i";
  p["rheology"] = "t";
  p["rheology_form"] = "table";  // two points: too few to fit
  return bed;
}

}  // namespace

TEST(MfmStage, MuOfIPlasticTakesTheRheologyOfItsGrainsAndRefusesOtherGrainsAtCheck) {
  TempDir work;
  // 1. Grains of another diameter than the DEM's: refused at check, before the DEM runs, through
  //    the grains the loader hands on from the dem stage through extract and tabulate.
  json stages = shearToTable();
  stages["bed"] = muOfIBed("1.5 mm");
  stages["bed"]["from"] = "table";
  writeText(work.path() / "other.json", json{{"name", "loop"}, {"stages", stages}}.dump(2));
  const auto other = runGrainbridge(work.path(), "check other.json");
  EXPECT_EQ(other.exitCode, 2) << other.output;
  EXPECT_NE(other.output.find("/stages/bed/params/rheology"), std::string::npos) << other.output;
  EXPECT_NE(other.output.find("other grains"), std::string::npos) << other.output;

  // 2. The DEM's grains: the bed runs with the table's points and says so.
  stages["bed"] = muOfIBed("1 mm");
  stages["bed"]["from"] = "table";
  writeText(work.path() / "loop.json", json{{"name", "loop"}, {"stages", stages}}.dump(2));
  const auto r = runGrainbridge(work.path(), "run loop.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const json summary =
      json::parse(readText(onlyInstance(work.path() / "results/loop/bed") / "manifest.json")).at("summary");
  const fs::path dbPath = work.path() / "results/loop/grainbridge.sqlite";
  {
    auto database = grainbridge::db::Database::openReadOnly(dbPath);
    const auto rheology = grainbridge::db::ClosureStore(database).loadRheology("t");
    EXPECT_EQ(summary.at("rheology_sha256"), rheology.sha256);
    ASSERT_EQ(rheology.rows.size(), 1u);
    const std::string points = std::to_string(rheology.rows.front().inertialNumbers.size()) + " points, I ";
    EXPECT_TRUE(summary.at("plastic_rheology").get<std::string>().starts_with("table: " + points))
        << summary.at("plastic_rheology");
  }

  // The plastic viscosity took part: the same bed with Schaeffer's settles otherwise.
  json schaeffer = muOfIBed("1 mm");
  schaeffer["params"]["plastic"] = "schaeffer";
  schaeffer["params"].erase("rheology");
  schaeffer["params"].erase("rheology_form");
  writeText(work.path() / "schaeffer.json", json{{"name", "schaeffer"}, {"stages", {{"bed", schaeffer}}}}.dump(2));
  ASSERT_EQ(runGrainbridge(work.path(), "run schaeffer.json -q").exitCode, 0);
  const json schaefferSummary =
      json::parse(readText(onlyInstance(work.path() / "results/schaeffer/bed") / "manifest.json")).at("summary");
  std::printf("mean height: mu_i %.9g, schaeffer %.9g\n", summary.at("mean_height").get<double>(),
              schaefferSummary.at("mean_height").get<double>());
  EXPECT_NE(summary.at("mean_height"), schaefferSummary.at("mean_height"));

  // 3. A workflow naming the rheology in the database (no `from`): planned from the database's
  //    grains, so other grains are refused at check there too, and the DEM's pass.
  for (const auto& [diameter, code] : {std::pair{"1.5 mm", 2}, std::pair{"1 mm", 0}}) {
    writeText(
        work.path() / "named.json",
        json{{"name", "named"}, {"database", dbPath.string()}, {"stages", {{"bed", muOfIBed(diameter)}}}}.dump(2));
    const auto check = runGrainbridge(work.path(), "check named.json");
    EXPECT_EQ(check.exitCode, code) << diameter << ": " << check.output;
    if (code != 0) {
      EXPECT_NE(check.output.find("/stages/bed/params/rheology"), std::string::npos) << check.output;
      EXPECT_NE(check.output.find("diameter 0.001 m"), std::string::npos) << check.output;
    }
  }
}

namespace {

// Copies of table "t"'s three quantities into the database as table `name`, with each node's
// standard error set to `error` (empty: none recorded).
void copyTable(const fs::path& dbPath, const std::string& name, const std::optional<double>& error) {
  auto database = grainbridge::db::Database::open(dbPath);
  database.transaction([&](grainbridge::db::Database& d) {
    grainbridge::db::ProvenanceStore provenance(d);
    const auto invocation = provenance.insertInvocation(grainbridge::db::test::sampleInvocation("copies"));
    const auto run = provenance.insertRun(grainbridge::db::test::sampleRun(invocation, "copy-" + name, "copies"));
    grainbridge::db::ClosureStore store(d);
    json rows = json::array();
    for (const char* q : {"p_theta", "eta_theta", "j_theta"}) {
      const auto t = store.loadTable("t", q);
      json errors = json::array();
      if (error) errors = std::vector<double>(t.table.values().size(), *error);
      rows.push_back({{"name", name},
                      {"quantity", q},
                      {"second_variable", ""},
                      {"solid_fractions", t.table.solidFractions()},
                      {"seconds", json::array()},
                      {"values", t.table.values()},
                      {"uncertainties", errors},
                      {"filters", {{"friction", t.friction}}}});
    }
    store.insertRecords(run, {{"closure_tables", rows}});
  });
}

json sampledBed(const std::string& table, int samples, int perQuantity, int seed) {
  json bed = looseBed();
  bed["params"]["closure_table"] = table;
  bed["params"]["closure_samples"] = samples;
  bed["params"]["closure_samples_per_quantity"] = perQuantity;
  bed["params"]["sample_seed"] = seed;
  return bed;
}

// Every instance folder of `stage` by its summary's closure_sample (0: the nominal run).
std::map<int, fs::path> samplesOf(const fs::path& stageDir) {
  std::map<int, fs::path> out;
  for (const auto& entry : fs::directory_iterator(stageDir)) {
    if (!fs::exists(entry.path() / "manifest.json")) continue;
    const json summary = json::parse(readText(entry.path() / "manifest.json")).at("summary");
    out[summary.value("closure_sample", 0)] = entry.path();
  }
  return out;
}

}  // namespace

TEST(MfmStage, ClosureSamplesDrawTheTablesWithinTheirErrorsReproduciblyAndNeedTablesWithErrors) {
  TempDir work;
  // 1. The tables, made upstream with the closure points' errors; the bed with two joint samples
  //    and one sample per quantity: six keyed instances, the samples labelled and moved.
  json stages = shearToTable();
  stages["bed"] = sampledBed("t", 2, 1, 7);
  stages["bed"]["from"] = "table";
  stages["beds"] = {{"type", "bed_compare"}, {"from", "bed"}};
  writeText(work.path() / "loop.json", json{{"name", "loop"}, {"stages", stages}}.dump(2));
  const auto r = runGrainbridge(work.path(), "run loop.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto beds = samplesOf(work.path() / "results/loop/bed");
  ASSERT_EQ(beds.size(), 6u);
  const auto series = [](const fs::path& dir) { return readText(dir / "series.csv"); };
  std::map<std::string, int> perturbed;
  const json nominalManifest = json::parse(readText(beds.at(0) / "manifest.json"));
  for (const auto& [k, dir] : beds) {
    const json manifest = json::parse(readText(dir / "manifest.json"));
    if (k == 0) {
      EXPECT_FALSE(manifest.at("summary").contains("closure_perturbed"));
      continue;
    }
    // Which sample it is is its draw (params, keyed) and its summary, one value: its sweep point
    // is its nominal run's.
    EXPECT_EQ(manifest.at("params").at("closure_draw").at("sample"), k);
    EXPECT_EQ(manifest.at("summary").at("closure_perturbed"), manifest.at("params").at("closure_draw").at("perturbed"));
    EXPECT_EQ(manifest.at("sweep_point"), nominalManifest.at("sweep_point"));
    perturbed[manifest.at("summary").at("closure_perturbed")]++;
    EXPECT_NE(series(dir), series(beds.at(0))) << "sample " << k << " ran on the nominal tables";
  }
  EXPECT_EQ(perturbed, (std::map<std::string, int>{{"all", 2}, {"p_theta", 1}, {"eta_theta", 1}, {"j_theta", 1}}));
  // bed_compare joins the samples to their nominal run: one row, with the spread of its two joint
  // samples' heights, and findings that lead with it.
  const fs::path compareDir = onlyInstance(work.path() / "results/loop/beds");
  std::istringstream csv(readText(compareDir / "beds.csv"));
  std::string headerLine, row, extra;
  std::getline(csv, headerLine);
  std::getline(csv, row);
  EXPECT_FALSE(std::getline(csv, extra) && !extra.empty()) << "a sample was compared as a run: " << extra;
  const auto header = splitCsvLine(headerLine);
  const auto fields = splitCsvLine(row);
  const auto at = [&](const std::string& name) {
    return fields.at(static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin()));
  };
  EXPECT_EQ(at("closure_samples"), "5");
  // Two samples' variance, (h1 - h2)^2 / 2, less the mean of their own squared errors.
  std::vector<double> heights, errors;
  for (int k = 1; k <= 2; ++k) {
    const json summary = json::parse(readText(beds.at(k) / "manifest.json")).at("summary");
    heights.push_back(summary.at("mean_height"));
    errors.push_back(summary.at("mean_height_err"));
  }
  const double variance = (heights[0] - heights[1]) * (heights[0] - heights[1]) / 2.0 -
                          (errors[0] * errors[0] + errors[1] * errors[1]) / 2.0;
  EXPECT_NEAR(std::stod(at("mean_height_closure")), std::sqrt(std::max(0.0, variance)), 1e-15);
  const json findings = json::parse(readText(compareDir / "manifest.json")).at("findings");
  const std::string headline = findings.at("headline");
  EXPECT_TRUE(headline.starts_with("bed: bed height ")) << headline;
  EXPECT_NE(headline.find("(bed fluctuations) ± "), std::string::npos) << headline;
  EXPECT_NE(headline.find("(DEM closures, 2 joint samples scattering by "), std::string::npos) << headline;

  // A sample cached before issue 57 has its number in its manifest's sweep point too. The
  // executor hands a comparing stage the plan's sweep point, so such a sample still joins its
  // nominal run when the comparison reruns over the cached beds.
  for (const auto& [k, dir] : beds) {
    if (k == 0) continue;
    json manifest = json::parse(readText(dir / "manifest.json"));
    manifest["sweep_point"]["closure_sample"] = k;
    writeText(dir / "manifest.json", manifest.dump(2));
  }
  fs::remove_all(compareDir);  // the comparison alone reruns; the beds stay cached
  const auto rerun = runGrainbridge(work.path(), "run loop.json -q");
  ASSERT_EQ(rerun.exitCode, 0) << rerun.output;
  ASSERT_EQ(json::parse(readText(beds.at(1) / "manifest.json")).at("sweep_point").value("closure_sample", 0), 1)
      << "the samples ran again instead of coming from the cache";
  std::istringstream rerunCsv(readText(onlyInstance(work.path() / "results/loop/beds") / "beds.csv"));
  std::string againHeader, againRow;
  std::getline(rerunCsv, againHeader);
  std::getline(rerunCsv, againRow);
  const auto names = splitCsvLine(againHeader);
  const auto values = splitCsvLine(againRow);
  EXPECT_EQ(
      values.at(static_cast<std::size_t>(std::find(names.begin(), names.end(), "closure_samples") - names.begin())),
      "5")
      << againRow;

  // `status --why` compares each instance with its own last run: a sample with the run of the
  // same draw, the nominal run with the run without one.
  json changed = stages;
  changed["bed"]["params"]["frames"] = 2;
  writeText(work.path() / "changed.json", json{{"name", "loop"}, {"stages", changed}}.dump(2));
  const auto why = runGrainbridge(work.path(), "status changed.json --why bed");
  ASSERT_EQ(why.exitCode, 0) << why.output;
  for (const std::string& label : {std::string("bed:"), std::string("bed[closure_sample=1]:"),
                                   std::string("bed[closure_perturbed=p_theta, closure_sample=3]:")}) {
    const auto from = why.output.find(label + " key changed since run");
    ASSERT_NE(from, std::string::npos) << label << "\n" << why.output;
    const auto next = why.output.find("\nbed", from + 1);
    const std::string lines = why.output.substr(from, next == std::string::npos ? std::string::npos : next - from);
    EXPECT_NE(lines.find("parameter frames: 1 -> 2"), std::string::npos) << lines;
    EXPECT_EQ(lines.find("closure_draw"), std::string::npos) << lines;
  }

  // 2. A sample is reproducible from its seed: the same bed in another workflow, reading the same
  //    tables from the database, repeats sample 1 bit for bit; another seed draws otherwise.
  const fs::path dbPath = work.path() / "results/loop/grainbridge.sqlite";
  const auto named = [&](const std::string& workflow, const json& bed) {
    writeText(work.path() / (workflow + ".json"),
              json{{"name", workflow}, {"database", dbPath.string()}, {"stages", {{"bed", bed}}}}.dump(2));
    const auto run = runGrainbridge(work.path(), "run " + workflow + ".json -q");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return samplesOf(work.path() / "results" / workflow / "bed");
  };
  const auto again = named("again", sampledBed("t", 2, 0, 7));
  ASSERT_EQ(again.size(), 3u);
  EXPECT_EQ(series(again.at(1)), series(beds.at(1)));
  EXPECT_EQ(series(again.at(0)), series(beds.at(0)));
  const auto other = named("other", sampledBed("t", 2, 0, 8));
  EXPECT_NE(series(other.at(1)), series(beds.at(1)));

  // 3. With every table error zero, each sample equals the nominal run bit for bit.
  copyTable(dbPath, "z", 0.0);
  const auto zero = named("zero", sampledBed("z", 2, 1, 7));
  ASSERT_EQ(zero.size(), 6u);
  for (const auto& [k, dir] : zero) {
    EXPECT_EQ(series(dir), series(zero.at(0))) << "sample " << k;
    const json a = json::parse(readText(dir / "manifest.json")).at("summary");
    const json b = json::parse(readText(zero.at(0) / "manifest.json")).at("summary");
    EXPECT_EQ(a.at("mean_height"), b.at("mean_height")) << "sample " << k;
  }

  // 4. Refused at check, naming the parameter: samples of a table without errors, and samples
  //    without closure "table".
  copyTable(dbPath, "n", std::nullopt);
  for (const auto& [bed, pointer] :
       {std::pair{sampledBed("n", 2, 0, 1), "/stages/bed/params/closure_samples"},
        std::pair{sampledBed("n", 0, 3, 1), "/stages/bed/params/closure_samples_per_quantity"}}) {
    writeText(work.path() / "bad.json",
              json{{"name", "bad"}, {"database", dbPath.string()}, {"stages", {{"bed", bed}}}}.dump(2));
    const auto check = runGrainbridge(work.path(), "check bad.json");
    EXPECT_EQ(check.exitCode, 2) << check.output;
    EXPECT_NE(check.output.find(pointer), std::string::npos) << check.output;
    EXPECT_NE(check.output.find("no standard errors"), std::string::npos) << check.output;
  }
  json kt = sampledBed("t", 2, 0, 1);
  kt["params"]["closure"] = "ktgf";
  writeText(work.path() / "kt.json",
            json{{"name", "kt"}, {"database", dbPath.string()}, {"stages", {{"bed", kt}}}}.dump(2));
  const auto check = runGrainbridge(work.path(), "check kt.json");
  EXPECT_EQ(check.exitCode, 2) << check.output;
  EXPECT_NE(check.output.find("/stages/bed/params/closure_samples"), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("closure \"table\""), std::string::npos) << check.output;
}

TEST(MfmStage, TsujiJetSmokeRunsOnTheSolverDefaultsAndPlotsThePressureDrop) {
  // configs/tsuji-jet-tfm-smoke.json: the Chapter 7 central jet (39 m/s into a packed 22 cm bed
  // of 4 mm grains) for 0.1 s on the solver's defaults, the case MFiX 21.3.2 aborts within
  // 0.13 s unless its residual normalisation is switched off.
  TempDir work;
  fs::copy_file(sourceDir() / "configs/tsuji-jet-tfm-smoke.json", work.path() / "smoke.json");
  const auto r = runGrainbridge(work.path(), "run smoke.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const fs::path bed = onlyInstance(work.path() / "results/tsuji-jet-tfm-smoke/bed");
  ASSERT_FALSE(bed.empty());
  const json summary = json::parse(readText(bed / "manifest.json")).at("summary");
  EXPECT_GT(summary.at("solver_steps").get<int>(), 0);
  EXPECT_TRUE(summary.contains("retries"));
  // The drop between the inlet and 20 cm carries (part of) the bed: positive, and below the
  // weight of the whole 22 cm bed by more than the averaging error.
  EXPECT_GT(summary.at("dp_jet").get<double>(), 0.0);
  EXPECT_LT(summary.at("dp_jet").get<double>() + summary.at("dp_jet_err").get<double>(),
            summary.at("bed_weight").get<double>());
  EXPECT_LT(std::abs(summary.at("solids_volume_change").get<double>()), 1e-6);
  // The comparing stage drew the pressure drop against time from the run's series.
  const fs::path jet = onlyInstance(work.path() / "results/tsuji-jet-tfm-smoke/jet_pressure");
  ASSERT_FALSE(jet.empty());
  EXPECT_TRUE(fs::exists(jet / "pressure_drop.svg"));
  const json findings = json::parse(readText(jet / "manifest.json")).at("findings");
  ASSERT_EQ(findings.at("rows").size(), 1u);
  EXPECT_NE(findings.at("headline").get<std::string>().find("mean particle height"), std::string::npos);
}

// average_to closes the window before the end of the run, as tfdem's does (issue 54): the window
// holds the samples from average_from to average_to, the summary's means are theirs.
TEST(MfmStage, AverageToEndsTheWindowBeforeTheRun) {
  TempDir work;
  json bed = json::parse(readText(sourceDir() / "configs/grain-fluidization-smoke.json"))["stages"]["bed"];
  bed.erase("sweep");
  auto& p = bed["params"];
  p["boundaries"][0]["gas_inflow"] = "0.5 m/s";
  p["duration"] = "0.05 s";
  p["output_interval"] = "0.01 s";
  p["average_from"] = "0.01 s";
  p["average_to"] = "0.03 s";
  p["frames"] = 1;
  const json wf = {{"name", "wf"}, {"stages", {{"bed", bed}}}};
  writeText(work.path() / "wf.json", wf.dump());
  const auto r = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const fs::path out = onlyInstance(work.path() / "results/wf/bed");
  const json summary = json::parse(readText(out / "manifest.json")).at("summary");
  EXPECT_EQ(summary.at("window_samples").get<int>(), 3);  // t = 0.01, 0.02, 0.03 s
  // And at check: the window must lie in the run.
  p["average_to"] = "0.06 s";
  writeText(work.path() / "bad.json", json({{"name", "bad"}, {"stages", {{"bed", bed}}}}).dump());
  const auto c = runGrainbridge(work.path(), "check bad.json");
  EXPECT_EQ(c.exitCode, 2);
  EXPECT_NE(c.output.find("/stages/bed/params/average_to: is after the end of the run (duration)"), std::string::npos)
      << c.output;
}

// Issue 56, item 4: a pressure outlet whose backflow carries solids lets them in although the
// interior beside it holds none. A column of still gas under a top outlet with backflow solids
// fraction 0.1: the sand falls in through the face. At most what free fall through the open face
// would bring in 0.2 s, 0.1 rho_p A g t^2 / 2; drag on 0.5 mm sand (terminal speed about 4 m/s)
// takes little of it. The old ghost rule (the interior's fraction, zero) let nothing in.
TEST(MfmStage, APressureOutletLetsItsSolidsBackflowIntoAnEmptyInterior) {
  TempDir work;
  const json wf = json::parse(R"({"name": "backflow", "stages": {"col": {"type": "mfm", "params": {
    "cells": [4, 8, 1], "lengths": ["8 cm", "16 cm", "2 cm"], "gravity": [0, "-9.81 m/s2", 0],
    "solids": [{"name": "sand", "diameter": "0.5 mm", "density": "2500 kg/m3", "restitution": 0.9}],
    "drag": "syamlal_obrien", "drag_c": 0.8, "drag_d": 2.65, "kinetic_model": "syamlal_algebraic",
    "granular_energy": "algebraic", "critical_void_fraction": 0.4,
    "boundaries": [{"side": "y_high", "kind": "pressure_outlet", "pressure": "101325 Pa", "solids_fractions": [0.1]}],
    "regions": [{"lo": [0, 0, 0], "hi": ["8 cm", "16 cm", "2 cm"], "solids_fractions": [0]}],
    "duration": "0.2 s", "output_interval": "0.05 s", "frames": 2, "progress": false}}}})");
  writeText(work.path() / "wf.json", wf.dump(2));
  const auto r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const json summary =
      json::parse(readText(onlyInstance(work.path() / "results/backflow/col") / "manifest.json")).at("summary");
  const double freeFall = 0.1 * 2500.0 * (0.08 * 0.02) * 0.5 * 9.81 * 0.2 * 0.2;
  const double in = summary.at("mass_in_sand").get<double>();
  EXPECT_GT(in, 0.7 * freeFall) << summary.dump();
  EXPECT_LT(in, freeFall) << summary.dump();
  EXPECT_LT(std::abs(summary.at("mass_balance_sand").get<double>()), 1e-10 * in) << summary.dump();
  EXPECT_EQ(summary.at("mass_out_sand").get<double>(), 0.0);
}

// `<family>_solver: petsc` (issue 58) on one rank: the Goldschmidt smoke bed's first 0.1 s with
// every family through PETSc's KSP (the default options: BiCGSTAB with point Jacobi) against the
// band LU. KSP
// stops at a relative residual of the family's tolerance (1e-6 momentum, 1e-8 pressure, 1e-10
// fraction), and an outer iteration stops at normalised residuals of 1e-4, so the runs differ by
// what those tolerances leave, not by round-off: measured 5e-7 of the bed's height (130 steps
// each, at 7.05 and 7.06 iterations); the bound is 1e-5, a tenth of the outer tolerance. Not equal to
// the bit either: KSP answered, not the LU a failed KSP falls back to. Both keep the solids
// inventory to round-off (the closing continuity solve of an inexact family is finished in flux
// form). Options PETSc cannot use are refused at check, naming the key.
TEST(MfmStage, PetscSolvesTheGoldschmidtSmokeAsTheBandLuDoesAndItsOptionsAreChecked) {
  TempDir work;
  const auto version = runGrainbridge(work.path(), "--version");
  if (version.output.find("fluid solver petsc: PETSc") == std::string::npos) GTEST_SKIP() << version.output;
  json config = json::parse(readText(sourceDir() / "configs/goldschmidt-mono-smoke.json"));
  config["stages"].erase("heights");
  json& bed = config["stages"]["bed"];
  bed.erase("sweep");
  bed["params"]["rotation_model"] = false;
  bed["params"]["duration"] = "0.1 s";
  bed["params"]["average_from"] = "0.05 s";
  bed["params"]["frames"] = 1;
  std::map<std::string, json> summaries;
  for (const std::string solver : {"direct", "petsc"}) {
    json c = config;
    c["name"] = solver;
    for (const char* family : {"momentum", "pressure", "fraction"})
      c["stages"]["bed"]["params"][std::string(family) + "_solver"] = solver;
    writeText(work.path() / (solver + ".json"), c.dump(2));
    const auto r = runGrainbridge(work.path(), "run " + solver + ".json -q");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    summaries[solver] =
        json::parse(readText(onlyInstance(work.path() / "results" / solver / "bed") / "manifest.json")).at("summary");
  }
  for (const auto& [solver, summary] : summaries)
    EXPECT_LT(std::abs(summary.at("solids_volume_change").get<double>()), 1e-12) << solver;
  const double direct = summaries["direct"].at("mean_height").get<double>();
  const double petsc = summaries["petsc"].at("mean_height").get<double>();
  EXPECT_NEAR(petsc, direct, 1e-5 * direct);
  EXPECT_NE(petsc, direct);
  EXPECT_NEAR(summaries["petsc"].at("bed_weight").get<double>(), summaries["direct"].at("bed_weight").get<double>(),
              1e-9 * summaries["direct"].at("bed_weight").get<double>());

  json bad = config;
  bad["name"] = "bad";
  bad["stages"]["bed"]["params"]["pressure_solver"] = "petsc";
  bad["stages"]["bed"]["params"]["pressure_petsc_options"] = "-ksp_type gmres -pc_type nosuch";
  writeText(work.path() / "bad.json", bad.dump(2));
  const auto refused = runGrainbridge(work.path(), "check bad.json");
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_NE(refused.output.find("/stages/bed/params/pressure_petsc_options"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("nosuch"), std::string::npos) << refused.output;
}
