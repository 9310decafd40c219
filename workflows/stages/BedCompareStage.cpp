#include "workflows/stages/BedCompareStage.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/io/FieldFrameReader.hpp"
#include "core/text/NumberText.hpp"
#include "engines/fluid/FrameMaps.hpp"
#include "workflows/contract/NumericCsv.hpp"
#include "workflows/report/BedArms.hpp"
#include "workflows/report/BedFigures.hpp"
#include "workflows/report/BedFindings.hpp"
#include "workflows/report/FindingsPage.hpp"
#include "workflows/report/Plot.hpp"
#include "workflows/report/Realisations.hpp"
#include "workflows/report/SweepLabel.hpp"
#include "workflows/stages/ClosureSamples.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;
using params::ParamSchema;
using params::ParamSpec;
using report::writtenText;
namespace units = core::units;

namespace {

std::shared_ptr<const ParamSchema> referenceSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::string("label").required().doc("what the value is, as the table heads it (\"Table 5.3\")"))
      .add(ParamSpec::string("kind")
               .defaultValue("reference")
               .options({"reference", "experiment"})
               .doc("a model's published value or a measurement (the figures' colour)"))
      .add(ParamSpec::quantity("mean_height", units::Dimension::lengthDim())
               .required()
               .positive()
               .doc("the time-averaged mean particle height (Eq. 5.22)"))
      .add(ParamSpec::stringList("match").defaultValue(json::array()).doc(
          "the runs it applies to, as \"<swept parameter>=<value as written in the sweep>\" or "
          "\"stage=<name>\", all of them to hold; none: every run"));
  return s;
}

std::shared_ptr<const ParamSchema> statementSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::string("text").required().doc(
             "what the reference says the runs should show, in its words (\"rotation lowers s_p at 1.30 m/s\")"))
      .add(ParamSpec::string("citation").required().doc("where it says so (\"Sun (2007), lines 1285-1294\")"));
  return s;
}

// The series a reference curve can be of, and the series column each is.
const std::vector<std::string> kReferenceOutputs = {"segregation_percentage", "mean_height"};

// A reference series' CSV: its time and value columns, or an Error naming the file and what is
// wrong with it.
std::pair<std::vector<double>, std::vector<double>> readReferenceSeries(const std::string& path) {
  const auto columns = contract::readNumericCsv(path);
  for (const char* column : {"time", "value"}) {
    if (!columns.contains(column))
      throw Error("reference series '" + path + "' has no column \"" + column + "\" (its header: time,value)");
  }
  const auto& time = columns.at("time");
  const auto& value = columns.at("value");
  if (time.empty()) throw Error("reference series '" + path + "' has no rows");
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (!std::isfinite(time[k]) || !std::isfinite(value[k]))
      throw Error("reference series '" + path + "': row " + std::to_string(k + 2) +
                  " holds a value that is not finite");
  }
  return {time, value};
}

// "k=v" split at the first '='; nullopt when there is none or either side is empty.
std::optional<std::pair<std::string, std::string>> splitMatch(const std::string& m) {
  const auto eq = m.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == m.size()) return std::nullopt;
  return std::make_pair(m.substr(0, eq), m.substr(eq + 1));
}

// Whether a run (its stage name and its sweep point as written) meets every "k=v" of a match.
bool matchesRun(const std::vector<std::pair<std::string, std::string>>& match, const std::string& stage,
                const json& written) {
  for (const auto& [k, v] : match) {
    if (k == "stage" ? stage != v : !written.contains(k) || writtenText(written[k]) != v) return false;
  }
  return true;
}

struct Reference {
  std::string label, kind;
  double height = 0.0;
  std::vector<std::pair<std::string, std::string>> match;
};

// One upstream bed run, with what the comparison reads of it: its products, never its params.
struct Bed {
  const UpstreamInstance* instance = nullptr;
  std::string label;       // "bed (gas_inflow 1.92 m/s, rotation_model true)"
  std::string panelTitle;  // the same, a line each: "bed\ngas_inflow 1.92 m/s\nrotation_model true"
  std::string closure;     // the colour key: the summary's closure (a kinetic model, or "table")
  std::string dp;          // the compared tap's summary key and series column: dp_<tap>
  json written;
  [[nodiscard]] double value(const std::string& k) const {
    const auto v = instance->summaryValue(k);
    return v ? v->value : NAN;
  }
  [[nodiscard]] bool matches(const Reference& r) const { return matchesRun(r.match, instance->stage(), written); }
};

// The time-averaged solid fraction (all phases) over the horizontal and vertical axes of the
// run's mean fields, averaged over the third axis.
report::FieldMap solidFractionMap(const Bed& bed) {
  const UpstreamInstance& up = *bed.instance;
  const auto files = up.artifactsOfKind("mean_field_frame");
  if (files.empty()) {
    throw Error("bed_compare: run " + bed.label + " (" + up.shortKey() +
                ") wrote no mean fields: give it an averaging window (average_from before duration)");
  }
  const auto frame = core::io::readFieldFrame(files.back());
  if (frame.materials.empty()) {
    throw Error("bed_compare: the mean fields of " + bed.label + " ('" + files.back().string() +
                "') carry no materials (gravity): rerun it with this grainbridge");
  }
  const fluid::PlaneMap plane = fluid::solidsFractionMap(frame);
  report::FieldMap map{bed.panelTitle, plane.columns, plane.rows, plane.x0, plane.y0, plane.dx, plane.dy, plane.values};
  return map;
}

}  // namespace

BedCompareStage::BedCompareStage() {
  schema_
      .add(ParamSpec::objectList("references", referenceSchema())
               .doc("published or measured mean particle heights, each for the runs it matches"))
      .add(ParamSpec::string("tap").defaultValue("").doc(
          "the pressure tap whose drop is compared and plotted (\"\": each run's first, its pressure_drop)"))
      .add(ParamSpec::string("realisations")
               .defaultValue("seed")
               .doc("the swept parameter whose values are independent realisations of one setting (the seed of the "
                    "initial perturbation): runs of a stage that differ only in it form an arm, given as mean, "
                    "standard deviation and standard error over its runs (arms.csv)"))
      .add(ParamSpec::inputFile("reference_series")
               .doc("a measured or published curve drawn beside the runs: a CSV with a header line time,value (s, "
                    "and the output's unit: % for s_p, m for a height), e.g. the experiment's 1 s means of s_p"))
      .add(ParamSpec::string("reference_series_of")
               .defaultValue("segregation_percentage")
               .options(kReferenceOutputs)
               .doc("the output the reference series is of, drawn in that output's figures"))
      .add(ParamSpec::string("reference_series_label")
               .defaultValue("experiment")
               .doc("the reference series' legend entry (\"Goldschmidt et al. (2003), 1 s means\")"))
      .add(ParamSpec::string("reference_series_citation")
               .defaultValue("")
               .doc("where the reference series' numbers come from, printed beside its label; required with it"))
      .add(ParamSpec::string("reference_series_kind")
               .defaultValue("experiment")
               .options({"reference", "experiment"})
               .doc("a measurement or a model's published values (the figures' colour)"))
      .add(ParamSpec::objectList("statements", statementSchema())
               .doc("what the reference says the runs should show, each with its source: printed in the findings "
                    "beside the runs' numbers"))
      .add(ParamSpec::string("title")
               .defaultValue("Multi-fluid beds side by side")
               .doesNotAffectResults()
               .doc("the findings' title"));
}

void BedCompareStage::checkParams(const json& p, const std::string& ptr, core::json::Diagnostics& d) const {
  if (p.contains("reference_series")) {
    if (p.at("reference_series_citation").get<std::string>().empty()) {
      d.add(
          ptr + "/reference_series_citation",
          "a reference series needs its source: give reference_series_citation (\"Goldschmidt et al. 2003, Fig. 9\")");
    }
    try {
      (void)readReferenceSeries(p.at("reference_series").at("path").get<std::string>());
    } catch (const Error& e) {
      d.add(ptr + "/reference_series", e.what());
    }
  }
  const json refs = p.value("references", json::array());
  for (std::size_t r = 0; r < refs.size(); ++r) {
    const json match = refs[r].value("match", json::array());
    for (std::size_t m = 0; m < match.size(); ++m) {
      if (!splitMatch(match[m].get<std::string>())) {
        d.add(ptr + "/references/" + std::to_string(r) + "/match/" + std::to_string(m),
              "expected \"<swept parameter>=<value>\" or \"stage=<name>\", found \"" + match[m].get<std::string>() +
                  "\"");
      }
    }
  }
}

void BedCompareStage::checkAgainstUpstream(const json& p, const std::string& ptr,
                                           const std::vector<UpstreamPlan>& upstream,
                                           core::json::Diagnostics& d) const {
  const std::string tap = p.at("tap");
  // What the comparison reads of every run, and the product each is.
  for (const auto& up : upstream) {
    const std::string from = "upstream stage " + up.stage;
    std::vector<std::string> missing;
    if (!up.records("mean_height")) missing.emplace_back("the summary value mean_height (Eq. 5.22)");
    if (tap.empty() ? !up.records("pressure_drop") || !up.records("pressure_drop_tap")
                    : !up.records("dp_" + tap) || !up.writesSeriesColumn("dp_" + tap)) {
      missing.push_back(tap.empty() ? "a pressure drop (pressure_drop, from a pressure tap)"
                                    : "the pressure drop dp_" + tap + " (a pressure tap named \"" + tap + "\")");
    }
    if (!up.output.fieldFrames) missing.emplace_back("field frames with their materials");
    if (!up.output.meanFieldFrames) missing.emplace_back("time-averaged fields (an averaging window)");
    if (missing.empty()) continue;
    std::string what;
    for (std::size_t k = 0; k < missing.size(); ++k) what += (k == 0 ? "" : "; ") + missing[k];
    d.add(ptr + (tap.empty() || up.records("dp_" + tap) ? "" : "/tap"),
          from + " does not produce " + what + ": bed_compare takes bed runs that do (mfm with solids, tfdem)");
    return;
  }
  // A reference series of s_p beside runs that record none would be drawn alone.
  if (p.contains("reference_series") && p.at("reference_series_of") == "segregation_percentage" &&
      std::none_of(upstream.begin(), upstream.end(),
                   [](const UpstreamPlan& up) { return up.writesSeriesColumn("segregation_percentage"); })) {
    d.add(ptr + "/reference_series_of",
          "no upstream run records segregation_percentage (a binary bed with `segregation`): the reference series "
          "would have no runs beside it");
  }
  // A realisation parameter named but swept by no upstream stage is a typo: every run would be an
  // arm of one. The default may select nothing (a comparison of single runs).
  const std::string realisations = p.at("realisations");
  const bool swept = std::any_of(upstream.begin(), upstream.end(), [&](const UpstreamPlan& up) {
    return (up.sweepWritten.empty() ? up.sweepPoint : up.sweepWritten).contains(realisations);
  });
  if (!swept && realisations != "seed") {
    d.add(ptr + "/realisations",
          "no upstream stage is swept over \"" + realisations +
              "\": name the swept parameter whose values are realisations, as the sweep writes it");
  }
  // A reference whose match selects no run (a parameter no run is swept over, a value not written
  // as in the sweep) would silently drop out of the comparison: refuse it now, not after the beds ran.
  const json refs = p.value("references", json::array());
  for (std::size_t r = 0; r < refs.size(); ++r) {
    const json match = refs[r].value("match", json::array());
    std::vector<std::pair<std::string, std::string>> pairs;
    bool wellFormed = true;
    for (std::size_t m = 0; m < match.size(); ++m) {
      const auto kv = splitMatch(match[m].get<std::string>());
      if (!kv) {
        wellFormed = false;
        continue;
      }
      pairs.push_back(*kv);
      const bool known = std::any_of(upstream.begin(), upstream.end(), [&](const UpstreamPlan& up) {
        return kv->first == "stage" ? up.stage == kv->second : up.sweepPoint.contains(kv->first);
      });
      if (!known) {
        d.add(ptr + "/references/" + std::to_string(r) + "/match/" + std::to_string(m),
              kv->first == "stage" ? "no upstream stage is named \"" + kv->second + "\""
                                   : "no upstream stage is swept over \"" + kv->first + "\"");
        wellFormed = false;
      }
    }
    if (!wellFormed) continue;
    const bool selects = std::any_of(upstream.begin(), upstream.end(), [&](const UpstreamPlan& up) {
      return matchesRun(pairs, up.stage, up.sweepWritten.empty() ? up.sweepPoint : up.sweepWritten);
    });
    if (!selects) {
      // Name the values the runs were written with, so a typo shows.
      std::string values;
      for (const auto& [k, v] : pairs) {
        if (k == "stage") continue;
        std::vector<std::string> seen;
        for (const auto& up : upstream) {
          const json& w = up.sweepWritten.empty() ? up.sweepPoint : up.sweepWritten;
          if (!w.contains(k)) continue;
          const std::string text = writtenText(w[k]);
          if (std::find(seen.begin(), seen.end(), text) == seen.end()) seen.push_back(text);
        }
        values += (values.empty() ? "" : "; ") + k + " is written";
        for (std::size_t i = 0; i < seen.size(); ++i) values += (i == 0 ? " " : ", ") + ("\"" + seen[i] + "\"");
      }
      d.add(ptr + "/references/" + std::to_string(r) + "/match",
            "matches no run: no upstream run meets all of it" + (values.empty() ? "" : " (" + values + ")") +
                "; write each value as the sweep writes it");
    }
  }
}

void BedCompareStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  if (ctx.inputs().empty()) throw Error("bed_compare: no upstream runs; give it \"from\" (mfm or tfdem stages)");
  std::vector<Reference> references;
  for (const auto& r : p.value("references", json::array())) {
    Reference ref{r.at("label"), r.at("kind"), r.at("mean_height"), {}};
    for (const auto& m : r.at("match")) ref.match.push_back(*splitMatch(m.get<std::string>()));
    references.push_back(std::move(ref));
  }
  const std::string tap = p.at("tap");

  // Closure samples of a run (issue 31), the runs whose summary records a closure_sample, join
  // their nominal run, the one of the same stage and sweep point that records none: they give its
  // spread from the DEM closures and are not runs of their own in the comparison.
  std::vector<const UpstreamInstance*> samples;
  std::vector<Bed> beds;
  for (const auto& up : ctx.inputs()) {
    if (up.summaryValue(kClosureSampleKey)) {
      samples.push_back(&up);
      continue;
    }
    Bed bed;
    bed.instance = &up;
    bed.written = up.sweepWritten();
    if (!up.hasSummary("mean_height")) {
      throw Error("bed_compare: upstream " + up.stage() + " (" + up.shortKey() +
                  ") has no mean_height: bed_compare takes bed runs with solids");
    }
    bed.closure = up.summaryText("closure", up.stageTypeLabel());
    const std::string firstTap = up.summaryText("pressure_drop_tap");
    if (tap.empty() && firstTap.empty()) {
      throw Error("bed_compare: upstream " + up.stage() + " (" + up.shortKey() + ") has no pressure tap");
    }
    bed.dp = "dp_" + (tap.empty() ? firstTap : tap);
    bed.panelTitle = up.stage();
    for (const auto& part : report::sweepParts(bed.written)) bed.panelTitle += "\n" + part;
    bed.label = report::sweepLabel(up.stage(), bed.written);
    beds.push_back(std::move(bed));
  }
  std::sort(beds.begin(), beds.end(), [](const Bed& a, const Bed& b) { return a.label < b.label; });
  // What tells each run from the others: the swept values that differ between them (and the
  // stage where stages differ), for the legends and the axes that name runs.
  std::vector<report::SweptRun> swept;
  for (const auto& bed : beds) swept.push_back({bed.instance->stage(), bed.written});
  const std::vector<std::vector<std::string>> distinct = report::distinguishingParts(swept);
  for (std::size_t r = 0; r < references.size(); ++r) {
    if (std::none_of(beds.begin(), beds.end(), [&](const Bed& b) { return b.matches(references[r]); })) {
      throw Error("bed_compare: /references/" + std::to_string(r) + " (" + references[r].label +
                  ") matches no run; its match values must be written as in the sweep");
    }
  }

  std::vector<std::vector<const UpstreamInstance*>> samplesOf(beds.size());
  for (const auto* sample : samples) {
    const auto nominal = std::find_if(beds.begin(), beds.end(), [&](const Bed& b) {
      return b.instance->stage() == sample->stage() && b.instance->sweepPoint() == sample->sweepPoint();
    });
    if (nominal == beds.end()) {
      throw Error("bed_compare: closure sample " + sample->stage() + " (" + sample->shortKey() +
                  ") has no nominal run among the upstream runs");
    }
    samplesOf[static_cast<std::size_t>(nominal - beds.begin())].push_back(sample);
  }

  // The report reads each run's products alone (report/BedRun): its summary, series and tables.
  std::vector<report::BedRun> runs;
  for (std::size_t b = 0; b < beds.size(); ++b) {
    const Bed& bed = beds[b];
    report::BedRun run;
    run.label = bed.label;
    for (const auto& part : distinct[b]) {
      run.shortLabel += (run.shortLabel.empty() ? "" : ", ") + part;
      run.category += (run.category.empty() ? "" : "\n") + part;
    }
    run.closure = bed.closure;
    run.meanHeight = bed.value("mean_height");
    run.meanHeightError = bed.value("mean_height_err");
    for (const auto& r : references) {
      if (bed.matches(r)) run.references.push_back({r.label, r.kind, r.height});
    }
    run.series = bed.instance->seriesColumns();
    for (const auto& phase : bed.instance->phases()) run.phases.push_back(phase.name);
    run.pressureDrop = bed.dp;
    run.segregationBlocks = bed.instance->artifactsOfKind("segregation_blocks_csv");
    run.profiles = bed.instance->artifactsOfKind("profiles_csv");
    for (const auto& [column, key] : std::vector<std::pair<std::string, std::string>>{
             {"pressure_drop", bed.dp},
             {"pressure_drop_err", bed.dp + "_err"},
             {"dp_frequency", bed.dp + "_frequency"},
             {"dp_amplitude", bed.dp + "_amplitude"},
             {"table_coverage_cell_steps", "table_coverage_cell_steps"},
             {"table_coverage_solids", "table_coverage_solids"},
             {"solver_steps", "solver_steps"},
             {"retries", "retries"},
             {"segregation_percentage", "segregation_percentage"},
             {"segregation_percentage_err", "segregation_percentage_err"},
             {"mean_height_fields", "mean_height_fields"},
             {"mean_height_fields_err", "mean_height_fields_err"},
             {"bed_weight", "bed_weight"},
             {"coordination", "coordination"},
             {"coordination_err", "coordination_err"},
             {"multi_contact_ratio", "multi_contact_ratio"},
             {"multi_contact_ratio_err", "multi_contact_ratio_err"}}) {
      run.values[column] = bed.value(key);
    }
    if (!samplesOf[b].empty()) {
      run.closureSamples = static_cast<int>(samplesOf[b].size());
      for (const std::string& output : report::kClosureSampledOutputs) {
        const std::string key = output == "pressure_drop" ? bed.dp : output;
        if (!std::isfinite(bed.value(key))) continue;
        std::vector<report::ClosureSampleValue> values;
        for (const auto* sample : samplesOf[b]) {
          const auto v = sample->summaryValue(key);
          if (!v)
            throw Error("bed_compare: closure sample " + sample->shortKey() + " of " + bed.label + " has no " + key);
          values.push_back({sample->summaryText(kClosurePerturbedKey, "all"), v->value, v->error});
        }
        run.closureSpreads[output] = report::closureSpread(values);
      }
    }
    runs.push_back(std::move(run));
  }
  std::vector<std::string> referenceLabels;
  for (const auto& r : references) {
    if (std::find(referenceLabels.begin(), referenceLabels.end(), r.label) == referenceLabels.end())
      referenceLabels.push_back(r.label);
  }
  contract::Findings findings = report::bedFindings(runs, referenceLabels, p.at("title").get<std::string>());
  core::writeFileAtomically(ctx.outputDir() / "beds.csv", report::bedsCsv(runs, referenceLabels));
  ctx.addArtifact("beds.csv", "csv");

  // Realisations (issue 55): the runs that differ only in `realisations` are one setting, an arm,
  // and the spread over them is what tells two settings apart; the findings lead with it.
  const std::string realisation = p.at("realisations");
  const std::vector<report::Arm> arms = report::groupArms(swept, realisation);
  const auto bedArms = report::bedArms(runs, arms);
  core::writeFileAtomically(ctx.outputDir() / "arms.csv", report::armsCsv(bedArms));
  ctx.addArtifact("arms.csv", "csv");
  // What the reference says and measured, beside the runs' numbers: its statements, then its curve.
  std::string reference;
  for (const auto& statement : p.value("statements", json::array())) {
    reference += "The reference: \u201c" + statement.at("text").get<std::string>() + "\u201d (" +
                 statement.at("citation").get<std::string>() + "). ";
  }
  std::vector<report::ReferenceSeries> referenceSeries;
  if (p.contains("reference_series")) {
    const std::string path = p.at("reference_series").at("path");
    auto [time, value] = readReferenceSeries(path);
    referenceSeries.push_back({p.at("reference_series_label"), p.at("reference_series_citation"),
                               p.at("reference_series_kind"), p.at("reference_series_of"), std::move(time),
                               std::move(value)});
    reference += "Beside the runs: " + referenceSeries.back().label + " (" + referenceSeries.back().citation + "), " +
                 std::to_string(referenceSeries.back().time.size()) + " points of " + referenceSeries.back().output +
                 " from " + std::filesystem::path(path).filename().string() + ". ";
  }
  findings.headline = report::armsHeadline(bedArms, realisation) + reference + findings.headline;

  // Figures: first, in a page's columns, the maps side by side, the averaged heights by run and a
  // binary bed's profiles; then, each at a page's full width, what several runs draw against time.
  auto addFigure = [&](const report::DrawnFigure& drawn, const std::string& caption, bool wide) {
    ctx.addArtifact(drawn.svg, "svg");
    ctx.addArtifact(drawn.png, "png");
    findings.figures.push_back({drawn.svg, drawn.png, caption, wide});
  };
  std::vector<report::FieldMap> maps;
  double highest = 0.0;
  for (const auto& bed : beds) {
    maps.push_back(solidFractionMap(bed));
    for (double v : maps.back().values) highest = std::max(highest, v);
  }
  addFigure(report::drawFieldMaps(maps, {"x", "m"}, {"height", "m"}, {"time-averaged solid fraction", "–"}, 0.0,
                                  std::max(0.6, highest), ctx.outputDir(), "solid_fraction_maps"),
            "Time-averaged solid fraction (all solids phases), one panel per run", false);

  addFigure(
      report::drawFigure(report::averagedHeightFigure(runs), ctx.outputDir(), "mean_height_averaged"),
      std::string("Time-averaged mean particle height per run (block-averaging errors) beside the reference values") +
          (samples.empty() ? "" : "; offset to its right, each sampled run's spread over its closure samples"),
      false);
  const auto binary = report::segregationFigures(runs, referenceSeries);
  if (!binary.profiles.series.empty()) {
    addFigure(report::drawFigure(binary.profiles, ctx.outputDir(), "profiles"),
              "Each phase's time-averaged solid fraction over the width against height", false);
  }
  findings.firstScreen = static_cast<int>(findings.figures.size());
  const auto realised =
      report::realisationsFigure(runs, arms, "segregation_percentage", "Segregation percentage s_p over realisations",
                                 report::kSegregationAxis, referenceSeries);
  if (!realised.series.empty()) {
    addFigure(report::drawFigure(realised, ctx.outputDir(), "segregation_realisations"),
              "Segregation percentage against time: per arm the mean over its realisations (line) ± one standard "
              "error across them (band)",
              true);
  }
  if (!binary.segregation.series.empty()) {
    addFigure(report::drawFigure(binary.segregation, ctx.outputDir(), "segregation_percentage"),
              "Segregation percentage against time: the samples (lines) and their 1 s means (points)", true);
  }
  const auto overTime = report::timeFigures(runs, tap, referenceSeries);
  addFigure(report::drawFigure(overTime.height, ctx.outputDir(), "mean_height"), "Mean particle height against time",
            true);
  addFigure(report::drawFigure(overTime.pressureDrop, ctx.outputDir(), "pressure_drop"), "Pressure drop against time",
            true);
  const auto contacts = report::contactFigure(runs);
  if (!contacts.series.empty()) {
    addFigure(report::drawFigure(contacts, ctx.outputDir(), "contact_numbers"),
              "Coordination number and multi-contact ratio against time, of the runs that record them (particle "
              "runs)",
              true);
  }
  ctx.setFindings(findings);

  report::writeFindingsPage(findings, "beds.csv", ctx.outputDir() / "bed_compare.html");
  ctx.addArtifact("bed_compare.html", "report_html");
  ctx.setSummary(json{{"beds", beds.size()}, {"arms", arms.size()}});
}

}  // namespace grainbridge::workflows::stages
