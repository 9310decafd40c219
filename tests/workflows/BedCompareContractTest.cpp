// The run-time stage contract (DESIGN.md, "Stage contracts"): bed_compare reads products — a
// summary's mean_height and pressure drop, series columns, field frames with their materials —
// so it takes any stage type that declares them, here a test-only one that is not mfm, and
// refuses at config load one that does not, naming the missing product.
#include <gtest/gtest.h>

#include <atomic>
#include <set>

#include "core/Files.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "core/json/Diagnostics.hpp"
#include "tests/support/Cli.hpp"
#include "workflows/config/WorkflowConfig.hpp"
#include "workflows/exec/Scheduler.hpp"
#include "workflows/exec/SerialDispatcher.hpp"
#include "workflows/exec/StopSignal.hpp"
#include "workflows/plan/Plan.hpp"
#include "workflows/stages/BedCompareStage.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace fs = std::filesystem;
using namespace grainbridge;
using namespace grainbridge::workflows;
using grainbridge::testing::readText;
using grainbridge::testing::TempDir;
using nlohmann::json;

namespace {

// A bed that is not a multi-fluid run: one phase "sand" whose frames, series and summary say the
// bed stands `height` high, `seed` millimetres more, with a segregation percentage of 0.5 + seed /
// 100. With `products` false it declares and writes only its summary.
class ToyBed final : public stages::StageType {
 public:
  ToyBed(std::string name, bool products) : name_(std::move(name)), products_(products) {
    schema_
        .add(params::ParamSpec::quantity("height", core::units::Dimension::lengthDim())
                 .defaultValue(0.02)
                 .positive()
                 .doc("mean particle height"))
        .add(params::ParamSpec::integer("seed").defaultValue(0).min(0).doc("a realisation: shifts the outputs"));
  }
  [[nodiscard]] std::string name() const override { return name_; }
  [[nodiscard]] int implVersion() const override { return 1; }
  [[nodiscard]] std::string summary() const override { return "test-only bed"; }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] stages::InputMode inputMode() const override { return stages::InputMode::None; }
  [[nodiscard]] std::optional<stages::PlannedOutput> plannedOutput(const json& /*resolved*/) const override {
    stages::PlannedOutput out;
    out.summaryKeys = {"mean_height", "pressure_drop", "pressure_drop_tap",
                       "dp_bed",      "closure",       "segregation_percentage"};
    if (products_) {
      out.fieldFrames = out.meanFieldFrames = true;
      out.seriesColumns = {"dp_bed", "mean_height_sand", "segregation_percentage"};
    }
    return out;
  }
  void run(stages::StageContext& ctx) const override {
    const int seed = ctx.params().at("seed");
    const double h = ctx.params().at("height").get<double>() + 1e-3 * seed;
    const double sp = 0.5 + seed / 100.0;
    if (products_) {
      core::data::FieldFrame frame;
      frame.grid.cells = {2, 4, 1};
      frame.grid.spacing = Vec3(0.01, 0.01, 0.01);
      const std::size_t n = frame.grid.cellCount();
      frame.ep_g.assign(n, 0.6);
      frame.p_g.assign(n, 101325.0);
      frame.u_g.assign(n, Vec3::Zero());
      frame.solids.push_back({"sand", std::vector<double>(n, 0.4), std::vector<Vec3>(n, Vec3::Zero()),
                              std::vector<double>(n, 0.0)});
      frame.materials.gravity = Vec3(0.0, -9.81, 0.0);
      frame.materials.species.push_back({"sand", 1e-3, 2500.0});
      const core::io::ArtifactStamp stamp{ctx.key()};
      core::io::FieldFrameWriter frames(ctx.outputDir(), stamp);
      ctx.addArtifact(frames.write(frame).lexically_relative(ctx.outputDir()).string(), "field_frame");
      core::io::FieldFrameWriter mean(ctx.outputDir() / "mean", stamp);
      ctx.addArtifact(mean.write(frame).lexically_relative(ctx.outputDir()).string(), "mean_field_frame");
      core::writeFileAtomically(ctx.outputDir() / "series.csv",
                                "time,dp_bed,mean_height_sand,segregation_percentage\n"
                                "0,100,0.01,0\n0.5,110," +
                                    std::to_string(h) + "," + std::to_string(sp) + "\n");
      ctx.addArtifact("series.csv", "csv");
    }
    ctx.setSummary({{"mean_height", h},
                    {"mean_height_err", 1e-4},
                    {"pressure_drop", 110.0},
                    {"pressure_drop_tap", "bed"},
                    {"dp_bed", 110.0},
                    {"closure", "toy"},
                    {"segregation_percentage", sp}});
  }

 private:
  std::string name_;
  bool products_;
  params::ParamSchema schema_;
};

stages::StageRegistry toyRegistry() {
  std::vector<std::unique_ptr<stages::StageType>> types;
  types.push_back(std::make_unique<ToyBed>("toy_bed", true));
  types.push_back(std::make_unique<ToyBed>("summary_only_bed", false));
  types.push_back(std::make_unique<stages::BedCompareStage>());
  return stages::StageRegistry(std::move(types));
}

json workflow(const std::string& bedType, const std::string& match) {
  return {{"name", "contract"},
          {"stages",
           {{"bed", {{"type", bedType}, {"sweep", {{"height", {0.02, "3 cm"}}}}}},
            {"beds",
             {{"type", "bed_compare"},
              {"from", "bed"},
              {"params",
               {{"references", {{{"label", "Table 5.3"}, {"mean_height", "2.1 cm"}, {"match", {match}}}}}}}}}}}};
}

// The instance folder of a stage that ran once.
fs::path instanceOf(const fs::path& stageDir) {
  fs::path dir;
  for (const auto& e : fs::directory_iterator(stageDir)) dir = e.path();
  return dir;
}

// Every problem of a config, or "" when it loads.
std::string loadProblems(const stages::StageRegistry& registry, const json& doc) {
  try {
    (void)config::parseWorkflow(doc, "contract.json", registry);
  } catch (const core::json::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(BedCompareContract, TakesAnyStageThatProducesHeightsPressureDropsAndFieldFrames) {
  const auto registry = toyRegistry();
  TempDir work;
  const auto cfg = config::parseWorkflow(workflow("toy_bed", "height=3 cm"), "contract.json", registry);
  const auto plan = plan::makePlan(cfg);
  exec::RunOptions options;
  options.workDir = work.path();
  exec::SerialDispatcher dispatcher(registry, exec::resultsRoot(work.path()), exec::stopFlag());
  ASSERT_EQ(exec::runWorkflow(cfg, plan, options, dispatcher, 1).exitCode(), 0);

  fs::path beds;
  for (const auto& e : fs::directory_iterator(work.path() / "results/contract/beds")) beds = e.path();
  const std::string csv = readText(beds / "beds.csv");
  // The run swept to 3 cm met its reference, 2.1 cm: +42.86 %, with the toy's closure as colour key.
  EXPECT_NE(csv.find("bed (height 3 cm),toy,0.03"), std::string::npos) << csv;
  EXPECT_NE(csv.find("Table 5.3,reference,0.021"), std::string::npos) << csv;
  // The other run has no reference, so one row of its own.
  EXPECT_NE(csv.find("bed (height 0.02),toy,0.02"), std::string::npos) << csv;
  // The maps' vertical axis came from the frames' gravity; the height plot from the phase's column.
  EXPECT_TRUE(fs::exists(beds / "solid_fraction_maps.svg"));
  EXPECT_NE(readText(beds / "mean_height.svg").find("height 3 cm"), std::string::npos);
}

TEST(BedCompareContract, RefusesAtCheckAStageWithoutTheProductsNamingWhatIsMissing) {
  const auto problems = loadProblems(toyRegistry(), workflow("summary_only_bed", "height=3 cm"));
  EXPECT_NE(problems.find("/stages/beds/params"), std::string::npos) << problems;
  EXPECT_NE(problems.find("upstream stage bed does not produce field frames with their materials"), std::string::npos)
      << problems;
  EXPECT_NE(problems.find("time-averaged fields"), std::string::npos) << problems;
}

TEST(BedCompareContract, RefusesAtCheckAReferenceWhoseMatchSelectsNoRun) {
  // 2.5 cm is not a value of the sweep: the reference would silently compare with nothing.
  const auto problems = loadProblems(toyRegistry(), workflow("toy_bed", "height=2.5 cm"));
  EXPECT_NE(problems.find("/stages/beds/params/references/0/match"), std::string::npos) << problems;
  EXPECT_NE(problems.find("matches no run"), std::string::npos) << problems;
  // The values the sweep wrote are named, so the typo shows.
  EXPECT_NE(problems.find("\"3 cm\""), std::string::npos) << problems;
  EXPECT_EQ(loadProblems(toyRegistry(), workflow("toy_bed", "height=0.02")), "");
}

// Issue 55: runs that differ only in their seed are realisations of one arm. Two heights, two
// seeds each: arms.csv has a row per arm with both seeds, a finite standard error, and the
// findings give the difference the height makes in standard errors.
TEST(BedCompareContract, GroupsRunsDifferingOnlyInTheSeedIntoArmsWithTheirStandardErrors) {
  const auto registry = toyRegistry();
  TempDir work;
  const json doc = {{"name", "contract"},
                    {"stages",
                     {{"bed", {{"type", "toy_bed"}, {"sweep", {{"height", {0.02, "3 cm"}}, {"seed", {1, 2}}}}}},
                      {"beds", {{"type", "bed_compare"}, {"from", "bed"}}}}}};
  const auto cfg = config::parseWorkflow(doc, "contract.json", registry);
  exec::RunOptions options;
  options.workDir = work.path();
  exec::SerialDispatcher dispatcher(registry, exec::resultsRoot(work.path()), exec::stopFlag());
  ASSERT_EQ(exec::runWorkflow(cfg, plan::makePlan(cfg), options, dispatcher, 1).exitCode(), 0);

  const fs::path beds = instanceOf(work.path() / "results/contract/beds");
  std::istringstream csv(readText(beds / "arms.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("arm,realisations,realisation_values,mean_height_mean,mean_height_sd,mean_height_se,", 0), 0u);
  // Heights 0.021 and 0.022: mean 0.0215, standard error 0.0005.
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("bed (height 0.02),2,1;2,0.0215,", 0), 0u) << line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("bed (height 3 cm),2,1;2,0.0315,", 0), 0u) << line;
  EXPECT_NE(line.find(",0.0005"), std::string::npos) << line;
  EXPECT_FALSE(std::getline(csv, line));

  const json manifest = json::parse(readText(beds / "manifest.json"));
  EXPECT_EQ(manifest.at("summary").at("arms"), 2);
  EXPECT_EQ(manifest.at("summary").at("beds"), 4);
  const std::string headline = manifest.at("findings").at("headline");
  EXPECT_NE(headline.find("bed (height 3 cm): s_p 0.5150 ± 0.0050 %, mean height 0.03150 ± 0.00050 m (mean and "
                          "standard error over 2 realisations: seed 1, 2)"),
            std::string::npos)
      << headline;
  // 0.01 m ± sqrt(2) 0.0005: 14 standard errors.
  EXPECT_NE(headline.find("bed: height 0.02 → 3 cm raises s_p by 0.0000 ± 0.0071 percentage points (0 standard "
                          "errors), raises mean height by 0.01000 ± 0.00071 m (14 standard errors); 2 realisations "
                          "each."),
            std::string::npos)
      << headline;
  EXPECT_TRUE(fs::exists(beds / "segregation_realisations.svg"));
}

namespace {

// The stroke colours of an SVG's lines, as gnuplot writes them: "rgb(  0, 114, 178)".
std::set<std::string> strokeColours(const std::string& svg) {
  std::set<std::string> colours;
  for (std::size_t at = svg.find("stroke='rgb("); at != std::string::npos; at = svg.find("stroke='rgb(", at + 1))
    colours.insert(svg.substr(at + 8, svg.find(')', at) - at - 7));
  return colours;
}

// Runs the workflow `doc` of toy beds; the bed_compare instance's folder.
fs::path runToyComparison(const json& doc, const fs::path& work) {
  const auto registry = toyRegistry();
  const auto cfg = config::parseWorkflow(doc, "contract.json", registry);
  exec::RunOptions options;
  options.workDir = work;
  exec::SerialDispatcher dispatcher(registry, exec::resultsRoot(work), exec::stopFlag());
  EXPECT_EQ(exec::runWorkflow(cfg, plan::makePlan(cfg), options, dispatcher, 1).exitCode(), 0);
  return instanceOf(work / "results/contract/beds");
}

}  // namespace

// Issue 62: a reader tells the runs apart at a glance. Each run gets its own colour in every
// figure, named by what differs between the runs (the height; not the stage, which all share),
// and the averaged heights put the runs along x by that name, not by row number.
TEST(BedCompareContract, GivesEachRunItsColourAndNamesRunsAlongXByWhatTellsThemApart) {
  TempDir work;
  const fs::path beds = runToyComparison(workflow("toy_bed", "height=3 cm"), work.path());
  const std::string height = readText(beds / "mean_height.svg");
  EXPECT_NE(height.find(">height 3 cm<"), std::string::npos) << "the legend names the swept value";
  EXPECT_EQ(height.find("bed (height"), std::string::npos) << "not the stage, which every run shares";
  const std::string blue = "rgb(  0, 114, 178)", vermillion = "rgb(213,  94,   0)";
  for (const char* figure : {"mean_height.svg", "pressure_drop.svg", "segregation_percentage.svg"}) {
    const auto colours = strokeColours(readText(beds / figure));
    EXPECT_TRUE(colours.contains(blue) && colours.contains(vermillion)) << figure << ": a colour per run";
  }
  const std::string averaged = readText(beds / "mean_height_averaged.svg");
  EXPECT_EQ(averaged.find("row of the table"), std::string::npos);
  EXPECT_NE(averaged.find(">height 0.02<"), std::string::npos) << "the runs are the axis' categories";
  EXPECT_NE(averaged.find(">run<"), std::string::npos) << "the axis is titled without a unit";
  // s_p in percent, and the figures against time take a page's full width.
  EXPECT_NE(readText(beds / "segregation_percentage.svg").find("segregation percentage s_p [%]"), std::string::npos);
  const json findings = json::parse(readText(beds / "manifest.json")).at("findings");
  for (const auto& figure : findings.at("figures")) {
    const std::string svg = figure.at("svg");
    const bool overTime = svg == "mean_height.svg" || svg == "pressure_drop.svg" || svg == "segregation_percentage.svg";
    EXPECT_EQ(figure.value("wide", false), overTime) << svg;
  }
  EXPECT_NE(std::string(findings.at("columns").back()).find("[%]"), std::string::npos);
  // The table names the runs as the legends do; beds.csv keeps the full label.
  EXPECT_EQ(findings.at("rows")[0][0], "height 0.02");
  EXPECT_NE(readText(beds / "beds.csv").find("bed (height 0.02)"), std::string::npos);
}

// A measured curve and the reference's words beside the runs: the curve drawn in the figures of
// its output with its label and citation, both named in the findings.
TEST(BedCompareContract, DrawsAReferenceSeriesAndPrintsTheReferencesStatementsBesideTheRuns) {
  TempDir work;
  const fs::path csv = work.path() / "experiment.csv";
  core::writeFileAtomically(csv, "time,value\n0.5,40\n1.5,55\n");
  json doc = workflow("toy_bed", "height=3 cm");
  json& p = doc["stages"]["beds"]["params"];
  p["reference_series"] = csv.string();
  p["reference_series_label"] = "the bed's 1 s means";
  p["reference_series_citation"] = "a notebook, p. 3";
  p["statements"] = {{{"text", "the taller bed segregates more"}, {"citation", "Sun (2007), line 1285"}}};
  const fs::path beds = runToyComparison(doc, work.path());
  const std::string sp = readText(beds / "segregation_percentage.svg");
  EXPECT_NE(sp.find("the bed's 1 s means (a notebook, p. 3)"), std::string::npos);
  EXPECT_EQ(readText(beds / "mean_height.svg").find("the bed's 1 s means"), std::string::npos) << "s_p's figures only";
  const std::string headline =
      json::parse(readText(beds / "manifest.json")).at("findings").at("headline").get<std::string>();
  EXPECT_NE(headline.find("The reference: \u201cthe taller bed segregates more\u201d (Sun (2007), line 1285)."),
            std::string::npos)
      << headline;
  EXPECT_NE(headline.find("Beside the runs: the bed's 1 s means (a notebook, p. 3), 2 points of segregation_percentage "
                          "from experiment.csv."),
            std::string::npos)
      << headline;
}

TEST(BedCompareContract, RefusesAtCheckAReferenceSeriesWithoutItsSourceOrItsValueColumn) {
  TempDir work;
  const fs::path csv = work.path() / "experiment.csv";
  core::writeFileAtomically(csv, "time,s_p\n0.5,40\n");
  json doc = workflow("toy_bed", "height=3 cm");
  doc["stages"]["beds"]["params"]["reference_series"] = csv.string();
  const std::string problems = loadProblems(toyRegistry(), doc);
  EXPECT_NE(problems.find("/stages/beds/params/reference_series_citation"), std::string::npos) << problems;
  EXPECT_NE(problems.find("has no column \"value\""), std::string::npos) << problems;
  EXPECT_NE(problems.find(csv.string()), std::string::npos) << "names the file: " << problems;
}
