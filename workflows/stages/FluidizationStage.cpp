#include "workflows/stages/FluidizationStage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/text/NumberText.hpp"
#include "engines/mfm/FluidizationCurve.hpp"
#include "workflows/contract/Findings.hpp"
#include "workflows/report/Plot.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;
using params::ParamSpec;

FluidizationStage::FluidizationStage() {
  schema_
      .add(ParamSpec::string("inflow")
               .defaultValue("superficial_gas_velocity")
               .doc("the summary value read as the superficial gas velocity U, m/s (the curve's abscissa)"))
      .add(ParamSpec::string("pressure_drop")
               .defaultValue("pressure_drop")
               .doc("the summary value read as the bed's pressure drop (its _err the error)"))
      .add(ParamSpec::string("title").defaultValue("Fluidization curves").doc("findings title"));
}

namespace {

struct Curve {
  std::vector<mfm::CurvePoint> points;
  double weight = std::numeric_limits<double>::quiet_NaN();   // bed_weight [Pa]
  double dragUmf = std::numeric_limits<double>::quiet_NaN();  // drag_umf [m/s]
  std::string model;                                          // the colour key: the upstream's type, a label
};

std::string percent(double measured, double reference) {
  std::ostringstream out;
  out.setf(std::ios::showpos);
  out.precision(2);
  out << std::fixed << 100.0 * (measured - reference) / reference << " %";
  return out.str();
}

}  // namespace

void FluidizationStage::checkAgainstUpstream(const json& p, const std::string& ptr,
                                             const std::vector<UpstreamPlan>& upstream,
                                             core::json::Diagnostics& d) const {
  const std::string inflow = p.at("inflow"), dpKey = p.at("pressure_drop");
  for (const auto& up : upstream) {
    if (!up.records(inflow)) {
      // Before summaries carried it, `inflow` named the upstream's swept parameter
      // ("boundaries/0/gas_inflow"): say what it names now.
      const bool parameterPath = inflow.find('/') != std::string::npos;
      d.add(ptr + "/inflow", "upstream stage " + up.stage + " records no \"" + inflow + "\"" +
                                 (parameterPath ? " (inflow names a summary value of the upstream, such as "
                                                  "superficial_gas_velocity, not a parameter)"
                                                : " (mfm and tfdem record superficial_gas_velocity)"));
      return;
    }
    if (!up.records(dpKey)) {
      d.add(ptr + "/pressure_drop",
            "upstream stage " + up.stage + " records no \"" + dpKey + "\" (give it a pressure tap, pressure_taps)");
      return;
    }
  }
}

void FluidizationStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  const std::string inflow = p.at("inflow"), dpKey = p.at("pressure_drop");
  std::map<std::string, Curve> curves;  // by upstream stage, in name order
  for (const auto& up : ctx.inputs()) {
    const auto u = up.summaryValue(inflow);
    if (!u) {
      throw Error("fluidization: upstream " + up.stage() + " (" + up.shortKey() + ") has no summary value " + inflow);
    }
    const auto dp = up.summaryValue(dpKey);
    if (!dp) {
      throw Error("fluidization: upstream " + up.stage() + " (" + up.shortKey() + ") has no summary value " + dpKey +
                  " (give that stage a pressure tap, pressure_taps)");
    }
    Curve& c = curves[up.stage()];
    c.model = up.stageTypeLabel();
    c.points.push_back({u->value, dp->value, std::isfinite(dp->error) ? dp->error : 0.0});
    if (const auto weight = up.summaryValue("bed_weight")) c.weight = weight->value;
    if (const auto umf = up.summaryValue("drag_umf")) c.dragUmf = umf->value;
  }
  if (curves.empty()) throw Error("fluidization: no upstream bed runs; give it \"from\"");

  contract::Findings findings;
  findings.title = p.at("title");
  findings.columns = {"stage",        "plateau",       "bed weight",         "plateau − weight",
                      "fluidization", "drag law U_mf", "fluidization − U_mf"};
  report::Figure fig;
  fig.title = "Pressure drop against inflow";
  fig.x = {"superficial gas velocity U", "m/s"};
  fig.y = {"time-averaged pressure drop Δp", "Pa"};
  json summary = {{"curves", curves.size()}};
  std::ostringstream headline, csv;
  csv.precision(std::numeric_limits<double>::max_digits10);
  csv << "stage,inflow,pressure_drop,pressure_drop_err\n";
  int variant = 0;
  double highest = 0.0, heaviest = 0.0;
  for (auto& [stage, c] : curves) {
    std::sort(c.points.begin(), c.points.end(), [](const auto& a, const auto& b) { return a.inflow < b.inflow; });
    report::Series s;
    s.label = stage;
    s.model = c.model;
    s.style = report::Series::Style::PointsWithErrors;
    s.variant = variant;
    for (const auto& pt : c.points) {
      s.x.push_back(pt.inflow);
      s.y.push_back(pt.pressureDrop);
      s.yError.push_back(pt.error);
      csv << stage << ',' << pt.inflow << ',' << pt.pressureDrop << ',' << pt.error << '\n';
      highest = std::max(highest, pt.inflow);
    }
    fig.series.push_back(std::move(s));
    if (std::isfinite(c.dragUmf)) {
      report::Series umf;  // the drag law's U_mf, a vertical line
      umf.label = stage + " U_mf (drag law)";
      umf.model = "syamlal_obrien";
      umf.style = report::Series::Style::Line;
      umf.variant = variant;
      umf.x = {c.dragUmf, c.dragUmf};
      umf.y = {0.0, std::isfinite(c.weight) ? 1.1 * c.weight : 0.0};
      fig.series.push_back(std::move(umf));
    }
    if (std::isfinite(c.weight)) heaviest = std::max(heaviest, c.weight);
    const auto r = mfm::readFluidizationCurve(c.points);
    std::vector<std::string> row{stage};
    if (r.found) {
      row.push_back(core::humanWithError(r.plateau, r.plateauError) + " Pa");
      summary["plateau_" + stage] = r.plateau;
      summary["plateau_" + stage + "_err"] = r.plateauError;
      summary["fluidization_velocity_" + stage] = r.fluidizationVelocity;
    } else {
      row.push_back("no plateau");
    }
    row.push_back(std::isfinite(c.weight) ? core::humanNumber(c.weight, 4) + " Pa" : "–");
    row.push_back(r.found && std::isfinite(c.weight) ? percent(r.plateau, c.weight) : "–");
    row.push_back(r.found ? core::humanNumber(r.fluidizationVelocity, 3) + " m/s" : "–");
    row.push_back(std::isfinite(c.dragUmf) ? core::humanNumber(c.dragUmf, 3) + " m/s" : "–");
    row.push_back(r.found && std::isfinite(c.dragUmf) ? percent(r.fluidizationVelocity, c.dragUmf) : "–");
    findings.rows.push_back(row);
    if (r.found) {
      headline << (headline.tellp() > 0 ? " " : "") << stage << ": plateau " << core::humanNumber(r.plateau, 4)
               << " Pa";
      if (std::isfinite(c.weight))
        headline << " against the bed weight " << core::humanNumber(c.weight, 4) << " Pa ("
                 << percent(r.plateau, c.weight) << ")";
      headline << ", fluidized at " << core::humanNumber(r.fluidizationVelocity, 3) << " m/s";
      if (std::isfinite(c.dragUmf))
        headline << " against the drag law's " << core::humanNumber(c.dragUmf, 3) << " m/s ("
                 << percent(r.fluidizationVelocity, c.dragUmf) << ")";
      headline << ".";
    } else {
      headline << (headline.tellp() > 0 ? " " : "") << stage << ": the curve reaches no plateau over the inflows run.";
    }
    ++variant;
  }
  if (heaviest > 0.0) {
    report::Series weight;
    weight.label = "bed weight";
    weight.model = "experiment";
    weight.style = report::Series::Style::Line;
    weight.x = {0.0, highest * 1.05};
    weight.y = {heaviest, heaviest};
    fig.series.push_back(std::move(weight));
  }
  core::writeFileAtomically(ctx.outputDir() / "fluidization.csv", csv.str());
  ctx.addArtifact("fluidization.csv", "csv");
  const auto drawn = report::drawFigure(fig, ctx.outputDir(), "fluidization");
  ctx.addArtifact(drawn.svg, "svg");
  ctx.addArtifact(drawn.png, "png");
  findings.figures.push_back({drawn.svg, drawn.png, fig.title});
  findings.headline = headline.str();
  ctx.setFindings(findings);
  ctx.setSummary(summary);
}

}  // namespace grainbridge::workflows::stages
