// The report layer (issue 16): figures through one plotting module that prints every label as
// written, findings that travel in a manifest, and a page that leads with them and summarises
// each instance's outputs in one line.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "core/Error.hpp"
#include "tests/support/Cli.hpp"
#include "workflows/contract/Findings.hpp"
#include "workflows/report/HtmlReport.hpp"
#include "workflows/report/Plot.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace fs = std::filesystem;
using namespace grainbridge;
using namespace grainbridge::testing;
using namespace grainbridge::workflows;
using nlohmann::json;

namespace {

report::Figure twoModelFigure() {
  report::Figure fig;
  fig.title = "τ* = −σxy / (ρ d² γ̇²)";
  fig.x = {"solid fraction φ", "–"};
  fig.y = {"τ*", "–", true};
  report::Series dem{"DEM, e 0.8", "DEM",       report::Series::Style::PointsWithErrors, 0, {0.1, 0.2},
                     {0.2, 0.3},   {0.01, 0.02}};
  report::Series kt{"syamlal_algebraic_mfix, e 0.8",
                    "syamlal_algebraic_mfix",
                    report::Series::Style::Line,
                    0,
                    {0.1, 0.2, 0.3},
                    {0.1, 0.2, 0.4},
                    {}};
  fig.series = {dem, kt};
  return fig;
}

}  // namespace

TEST(Plot, DrawsSvgAndPngWithLabelsPrintedLiterally) {
  TempDir dir;
  const auto drawn = report::drawFigure(twoModelFigure(), dir.path(), "fig");
  ASSERT_TRUE(fs::exists(dir.path() / drawn.svg));
  ASSERT_TRUE(fs::exists(dir.path() / drawn.png));
  const std::string svg = readText(dir.path() / drawn.svg);
  // Enhanced text would split the name at each underscore into sub-scripted <tspan>s.
  EXPECT_NE(svg.find("syamlal_algebraic_mfix, e 0.8"), std::string::npos);
  EXPECT_NE(svg.find("solid fraction φ [–]"), std::string::npos);
  EXPECT_NE(svg.find("τ* [–]"), std::string::npos);
  for (const char* markup : {"{/", "_{", "^{", "@"}) EXPECT_EQ(svg.find(markup), std::string::npos) << markup;
  // The model's colour is the one every figure gives it.
  const std::string hex = report::seriesColour("syamlal_algebraic_mfix");  // "#rrggbb"
  char rgb[32];
  std::snprintf(rgb, sizeof rgb, "rgb(%3ld, %3ld, %3ld)", std::stol(hex.substr(1, 2), nullptr, 16),
                std::stol(hex.substr(3, 2), nullptr, 16), std::stol(hex.substr(5, 2), nullptr, 16));
  EXPECT_NE(svg.find(rgb), std::string::npos) << rgb;
  EXPECT_EQ(svg.find("date"), std::string::npos);
  // Equal data, equal files.
  const auto again = report::drawFigure(twoModelFigure(), dir.path(), "fig2");
  EXPECT_EQ(readText(dir.path() / again.svg), svg);
  EXPECT_EQ(readText(dir.path() / again.png), readText(dir.path() / drawn.png));
}

// A tall narrow bed's map (the 15 x 90 cm jet) labels its x axis at the ends only: three labels
// overlapped in its narrow panel (issue 54). A square one keeps the middle label.
TEST(Plot, NarrowMapsLabelOnlyTheirEnds) {
  TempDir dir;
  auto map = [](int columns, int rows, double dx, double dy) {
    report::FieldMap m;
    m.title = "run";
    m.columns = columns;
    m.rows = rows;
    m.dx = dx;
    m.dy = dy;
    m.values.assign(static_cast<std::size_t>(columns * rows), 0.3);
    return m;
  };
  const report::Axis x{"x", "m"}, y{"height", "m"}, colour{"solids fraction", "–"};
  const auto narrow = report::drawFieldMaps({map(15, 45, 0.01, 0.02), map(15, 45, 0.01, 0.02)}, x, y, colour, 0.0,
                                            0.6, dir.path(), "narrow");
  const std::string narrowSvg = readText(dir.path() / narrow.svg);
  EXPECT_EQ(narrowSvg.find(">0.075<"), std::string::npos);
  EXPECT_NE(narrowSvg.find(">0.15<"), std::string::npos);
  const auto square = report::drawFieldMaps({map(15, 15, 0.01, 0.01)}, x, y, colour, 0.0, 0.6, dir.path(), "square");
  EXPECT_NE(readText(dir.path() / square.svg).find(">0.075<"), std::string::npos);
}

TEST(Plot, RefusesAnAxisWithoutUnitAndRaggedSeries) {
  TempDir dir;
  auto fig = twoModelFigure();
  fig.y.unit.clear();
  EXPECT_THROW(report::drawFigure(fig, dir.path(), "f"), Error);
  fig = twoModelFigure();
  fig.series[0].yError.pop_back();
  EXPECT_THROW(report::drawFigure(fig, dir.path(), "f"), Error);
}

TEST(Plot, ModelColoursAreFixedAndDistinct) {
  EXPECT_EQ(report::seriesColour("lun1984"), report::seriesColour("lun1984"));
  EXPECT_NE(report::seriesColour("lun1984"), report::seriesColour("syamlal_algebraic"));
  EXPECT_NE(report::seriesColour("DEM"), report::seriesColour("experiment"));
}

// Runs side by side (issue 62): each its own colour, none of them a reference kind's, and runs
// along x by name, the axis titled without a unit; a wide figure is drawn for a page's width.
TEST(Plot, RunsHaveTheirOwnColoursAndAreCategoriesAlongX) {
  std::set<std::string> colours;
  for (std::size_t r = 0; r < 6; ++r) colours.insert(report::runColour(r));
  EXPECT_EQ(colours.size(), 6u);
  EXPECT_FALSE(colours.contains(report::seriesColour("experiment")));
  EXPECT_FALSE(colours.contains(report::seriesColour("reference")));
  EXPECT_EQ(report::runColour(6), report::runColour(0));

  TempDir dir;
  report::Figure fig{"heights",
                     {"run", "", false, {"rotation_model false", "rotation_model true\nseed 2"}},
                     {"mean particle height", "m"},
                     {}};
  for (std::size_t r = 0; r < 2; ++r) {
    report::Series s{"run " + std::to_string(r),
                     "lun1984",
                     report::Series::Style::Points,
                     0,
                     {static_cast<double>(r + 1)},
                     {0.1},
                     {},
                     report::runColour(r)};
    fig.series.push_back(s);
  }
  const std::string svg = readText(dir.path() / report::drawFigure(fig, dir.path(), "runs").svg);
  EXPECT_NE(svg.find(">rotation_model false<"), std::string::npos);
  EXPECT_NE(svg.find(">seed 2<"), std::string::npos) << "a category's second line";
  EXPECT_NE(svg.find(">run<"), std::string::npos);
  EXPECT_EQ(svg.find("run ["), std::string::npos);
  // Each series in its run's colour, not its model's (lun1984's blue is run 0's: run 1 tells).
  EXPECT_NE(svg.find("rgb(213,  94,   0)"), std::string::npos);
  EXPECT_EQ(svg.find("width=\"1200"), std::string::npos);
  fig.wide = true;
  EXPECT_NE(readText(dir.path() / report::drawFigure(fig, dir.path(), "wide").svg).find("width=\"1200"),
            std::string::npos);
  // Categories belong on x; a unitless y is refused as before.
  fig.y.categories = {"a"};
  EXPECT_THROW(report::drawFigure(fig, dir.path(), "f"), Error);
}

TEST(Findings, TravelThroughJsonAndPrintAsAlignedText) {
  contract::Findings f;
  f.title = "DEM against kinetic theory";
  f.headline = "Largest deviation from lun1984: −16.9 % in τ* at φ 0.1, e 0.8.";
  f.columns = {"largest deviation from", "τ*"};
  f.rows = {{"lun1984", "−16.9 % (φ 0.1, e 0.8)"}, {"syamlal_algebraic", "+624 % (φ 0.1, e 0.9)"}};
  f.figures = {{"a.svg", "a.png", "τ*"}, {"b.svg", "b.png", "s_p against time", true}};
  f.firstScreen = 1;
  const auto back = contract::Findings::fromJson(json::parse(f.toJson().dump()));
  EXPECT_EQ(back.toJson(), f.toJson());
  EXPECT_FALSE(back.figures[0].wide);
  EXPECT_TRUE(back.figures[1].wide);
  const std::string text = contract::findingsText(f);
  EXPECT_NE(text.find(f.headline), std::string::npos);
  // The τ* column starts at the same character in every line, UTF-8 or not.
  std::istringstream lines(text);
  std::vector<std::size_t> starts;
  for (std::string line; std::getline(lines, line);) {
    for (const char* cell : {"τ*", "−16.9", "+624"}) {
      const auto at = line.find(cell);
      if (at == std::string::npos || line.find("Largest") != std::string::npos) continue;
      std::size_t codePoints = 0;
      for (std::size_t i = 0; i < at; ++i) codePoints += (static_cast<unsigned char>(line[i]) & 0xC0) != 0x80;
      starts.push_back(codePoints);
    }
  }
  ASSERT_EQ(starts.size(), 3u);
  EXPECT_EQ(starts[0], starts[1]);
  EXPECT_EQ(starts[1], starts[2]);
}

// A dem-like instance with 120 frames and a compare-like instance with findings.
class ReportPage : public ::testing::Test {
 protected:
  void SetUp() override {
    const fs::path shear = root.path() / "wf/shear/abc";
    fs::create_directories(shear / "frames");
    json artifacts = json::array();
    for (int i = 0; i < 120; ++i) {
      const std::string p = "frames/particles_" + std::to_string(i) + ".h5";
      writeText(shear / p, "x");
      artifacts.push_back({{"path", p}, {"kind", "particle_frame"}});
    }
    writeText(shear / "particles.xmf", "<Xdmf/>");
    artifacts.push_back({{"path", "particles.xmf"}, {"kind", "xdmf"}});
    const double side = 13.7823 * 1e-3;
    instances.emplace_back("shear", "dem", std::string(64, 'a'), shear,
                         json{{"sweep_point", {{"box_hi", {side, side, side}}}},
                              {"sweep_written", {{"box_hi", {"13.7823 mm", "13.7823 mm", "13.7823 mm"}}}},
                              {"summary", {{"final_coordination", 0.012}, {"steps", 600000}}},
                              {"artifacts", artifacts}});
    const fs::path kt = root.path() / "wf/kt/def";
    fs::create_directories(kt);
    report::drawFigure(twoModelFigure(), kt, "compare_tau_shear");
    contract::Findings f;
    f.title = "DEM against kinetic theory";
    f.headline = "Largest deviation from lun1984: −16.9 % in τ*.";
    f.columns = {"largest deviation from", "τ*"};
    f.rows = {{"lun1984", "−16.9 % (φ 0.1, e 0.8)"}};
    f.figures = {{"compare_tau_shear.svg", "compare_tau_shear.png", "τ*"}};
    instances.emplace_back("kt", "compare", std::string(64, 'b'), kt,
                         json{{"summary", {{"points", 6}}},
                              {"findings", f.toJson()},
                              {"artifacts",
                               {{{"path", "compare_tau_shear.svg"}, {"kind", "svg"}},
                                {{"path", "compare_tau_shear.png"}, {"kind", "png"}}}}});
    out = root.path() / "wf/report";
    fs::create_directories(out);
  }
  TempDir root;
  std::vector<workflows::contract::UpstreamInstance> instances;
  fs::path out;
};

TEST_F(ReportPage, LeadsWithFindingsAndSummarisesOutputsInOneLine) {
  const auto files = report::writeHtmlReport({"t", "results/wf/grainbridge.sqlite", workflows::stages::StageRegistry::builtin().reportView()}, instances, out, out);
  ASSERT_EQ(files.findings.size(), 1u);
  const std::string page = readText(out / "report.html");
  const auto findings = page.find("<section id=\"findings\">");
  ASSERT_NE(findings, std::string::npos);
  EXPECT_LT(findings, page.find("Stage shear"));
  EXPECT_NE(page.find("figures first-screen"), std::string::npos);
  EXPECT_NE(page.find("../kt/def/compare_tau_shear.svg"), std::string::npos);
  // Not one link per frame: the folder and the .xmf.
  EXPECT_EQ(page.find("particles_7.h5"), std::string::npos);
  EXPECT_NE(page.find("121 files"), std::string::npos);
  EXPECT_NE(page.find("../shear/abc/particles.xmf"), std::string::npos);
  // The sweep as written, its SI value beside it; no binary noise for people.
  EXPECT_NE(page.find("13.7823 mm (×3)"), std::string::npos);
  EXPECT_NE(page.find("0.0137823 (×3) m"), std::string::npos);
  EXPECT_EQ(page.find("0.013782299999999999"), std::string::npos);
  // The footer names the build and the database.
  EXPECT_NE(page.find("<footer>Made by grainbridge"), std::string::npos);
  EXPECT_NE(page.find("results/wf/grainbridge.sqlite"), std::string::npos);
  // The stage's CSV keeps every digit.
  const std::string csv = readText(out / "stage_shear.csv");
  EXPECT_NE(csv.find("0.013782299999999999"), std::string::npos) << csv;
}

TEST_F(ReportPage, EveryTableRowHoldsAtMostTwoLinks) {
  report::writeHtmlReport({"t", "", workflows::stages::StageRegistry::builtin().reportView()}, instances, out, out);
  const std::string page = readText(out / "report.html");
  const std::regex row("<tr>(.*?)</tr>");
  int rows = 0;
  for (auto it = std::sregex_iterator(page.begin(), page.end(), row); it != std::sregex_iterator(); ++it, ++rows) {
    const std::string r = (*it)[1];
    std::size_t links = 0;
    for (auto at = r.find("<a "); at != std::string::npos; at = r.find("<a ", at + 1)) ++links;
    EXPECT_LE(links, 2u) << r;
  }
  EXPECT_GE(rows, 3);
}

// Issue 57: a closure sample records which sample it is in its summary, not its sweep point; the
// page shows it beside the sweep point from there (the mfm type declares it), so a sample's row is
// told apart from its nominal run's.
TEST(ReportPageOfSamples, ShowsWhichClosureSampleARowIsBesideItsSweepPoint) {
  TempDir root;
  std::vector<workflows::contract::UpstreamInstance> beds;
  const json point = {{"boundaries/0/gas_inflow", 0.207}};
  const json written = {{"boundaries/0/gas_inflow", "20.7 cm/s"}};
  for (int k = 0; k <= 2; ++k) {
    json summary = {{"mean_height", 0.05 + 0.001 * k}, {"closure", "table"}};
    if (k > 0) {
      summary["closure_sample"] = k;
      summary["closure_perturbed"] = k == 1 ? "all" : "p_theta";
    }
    const fs::path dir = root.path() / "wf/bed" / std::to_string(k);
    fs::create_directories(dir);
    beds.emplace_back("bed", "mfm", std::string(64, static_cast<char>('a' + k)), dir,
                      json{{"sweep_point", point}, {"sweep_written", written}, {"summary", summary}});
  }
  const fs::path out = root.path() / "wf/report";
  fs::create_directories(out);
  report::writeHtmlReport({"t", "", workflows::stages::StageRegistry::builtin().reportView()}, beds, out, out);
  const std::string page = readText(out / "report.html");
  const auto header = page.find("<th>boundaries/0/gas_inflow</th><th>closure_sample</th><th>closure_perturbed</th>");
  ASSERT_NE(header, std::string::npos) << page;
  EXPECT_NE(page.find("<td>2</td><td>p_theta</td>", header), std::string::npos) << page;
  EXPECT_NE(page.find("<td>1</td><td>all</td>", header), std::string::npos) << page;
  // The nominal run's cells are empty.
  EXPECT_NE(page.find("</td><td></td><td></td>", header), std::string::npos) << page;
}
