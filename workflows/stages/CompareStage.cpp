#include "workflows/stages/CompareStage.hpp"

#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "core/ClosureForms.hpp"
#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/Log.hpp"
#include "core/io/XdmfText.hpp"
#include "engines/closures/KineticModel.hpp"
#include "workflows/report/GnuplotFigure.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;
using params::ParamSpec;
namespace kt = grainbridge::closures;

CompareStage::CompareStage() {
  schema_
      .add(ParamSpec::string("model")
               .defaultValue("lun1984")
               .options({"lun1984", "syamlal_algebraic", "syamlal_algebraic_mfix"})
               .doc("the model the summary's deviations refer to (every model is in the CSV and plots)"))
      .add(ParamSpec::number("summary_max_solid_fraction")
               .defaultValue(0.2)
               .min(0.0)
               .doc("the summary's largest deviation is over points up to this solid fraction"))
      .add(ParamSpec::string("title").defaultValue("DEM closures against kinetic theory").doc("page title"));
}

namespace {

// One DEM closure point, from an extract instance's summary.
struct Point {
  std::string key;
  double solidFraction = 0, restitution = 1, friction = 0, shearRate = 0, diameter = 0, density = 0;
  json summary;
  [[nodiscard]] bool has(const char* q) const { return summary.contains(q) && summary[q].is_number(); }
  [[nodiscard]] double value(const char* q) const { return summary.at(q).get<double>(); }
  [[nodiscard]] double error(const std::string& q) const {
    const std::string e = q + "_err";
    return summary.contains(e) && summary[e].is_number() ? summary[e].get<double>() : 0.0;
  }
};

struct Prediction {
  double pShear = NAN, tauShear = NAN, tShear = NAN;  // steady simple shear (shear units)
  double pTheta = NAN, jTheta = NAN, etaTheta = NAN;  // at any temperature
};

Prediction predict(kt::KineticModelName model, double solidFraction, double restitution, double shearRate,
                   double diameter, double density) {
  kt::KineticState s;
  s.solidFraction = solidFraction;
  s.restitution = restitution;
  s.diameter = diameter;
  s.density = density;
  s.granularTemperature = 1.0;  // theta = 1 m^2/s^2: each coefficient at unit temperature
  const auto unit = kt::evaluate(model, s);
  // At unit temperature each theta form is its coefficient; steady shear's temperature is where
  // the shear work mu gammadot^2 balances the dissipation J (both proportional to theta^(3/2)).
  using core::ClosureForm;
  const core::ClosureFormState atUnitTemperature{density, diameter, 1.0, shearRate};
  Prediction out;
  out.pTheta = core::toClosureForm(ClosureForm::PTheta, unit.pressure, atUnitTemperature);
  out.etaTheta = core::toClosureForm(ClosureForm::EtaTheta, unit.shearViscosity, atUnitTemperature);
  out.jTheta = core::toClosureForm(ClosureForm::JTheta, unit.dissipationRate, atUnitTemperature);
  if (shearRate > 0.0 && unit.dissipationRate > 0.0) {
    const double T = unit.shearViscosity / unit.dissipationRate * shearRate * shearRate;
    out.tShear = core::toClosureForm(ClosureForm::TShear, T, atUnitTemperature);
    out.pShear = core::toClosureForm(ClosureForm::PShear, unit.pressure * T, atUnitTemperature);
    out.tauShear =
        core::toClosureForm(ClosureForm::TauShear, unit.shearViscosity * std::sqrt(T) * shearRate, atUnitTemperature);
  }
  return out;
}

double predicted(const Prediction& p, const std::string& q) {
  if (q == "p_shear") return p.pShear;
  if (q == "tau_shear") return p.tauShear;
  if (q == "t_shear") return p.tShear;
  if (q == "p_theta") return p.pTheta;
  if (q == "eta_theta") return p.etaTheta;
  return p.jTheta;
}

const std::map<std::string, std::string>& quantityLabels() {
  static const std::map<std::string, std::string> labels = [] {
    std::map<std::string, std::string> out;
    for (const auto& f : core::closureForms()) out[std::string(f.name)] = std::string(f.label);
    return out;
  }();
  return labels;
}

}  // namespace

void CompareStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  const auto primary = kt::kineticModelFromString(p.at("model").get<std::string>());
  std::vector<Point> points;
  for (const auto& up : ctx.inputs()) {
    if (up.stageType != "extract") {
      throw Error("compare: upstream " + up.stage + " is a " + up.stageType + " stage; compare takes extract stages");
    }
    Point pt;
    pt.key = up.key;
    pt.summary = up.manifest.at("summary");
    pt.solidFraction = pt.value("solid_fraction");
    pt.diameter = pt.value("diameter");
    pt.density = pt.value("density");
    if (!pt.has("restitution")) {
      throw Error("compare: the closure point of " + up.stage + " (" + up.key.substr(0, 12) +
                  ") has no restitution: its frames do not come from a dem stage");
    }
    pt.restitution = pt.value("restitution");
    pt.friction = pt.has("friction") ? pt.value("friction") : 0.0;
    pt.shearRate = pt.has("shear_rate") ? pt.value("shear_rate") : 0.0;
    points.push_back(std::move(pt));
  }
  if (points.empty()) throw Error("compare: no upstream extract instances; give it \"from\"");
  std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) {
    return std::tie(a.restitution, a.friction, a.solidFraction) < std::tie(b.restitution, b.friction, b.solidFraction);
  });

  const std::vector<std::string> quantities = {"p_shear", "tau_shear", "t_shear", "p_theta", "eta_theta", "j_theta"};
  std::ostringstream csv;
  csv.precision(10);
  // The state identifies the point; which extract run it came from is in the database
  // (run_inputs), not here, so the CSV does not change when an upstream key does.
  csv << "solid_fraction,restitution,friction,shear_rate,quantity,dem,dem_err,model,prediction,deviation\n";
  json summary = {{"model", kt::toString(primary)}, {"points", points.size()}};
  const double limit = p.at("summary_max_solid_fraction");
  std::map<std::string, double> worst;
  for (const auto& pt : points) {
    for (auto model : kt::kAllKineticModels) {
      const auto pred = predict(model, pt.solidFraction, pt.restitution, pt.shearRate, pt.diameter, pt.density);
      for (const auto& q : quantities) {
        if (!pt.has(q.c_str())) continue;
        const double kt = predicted(pred, q);
        if (!std::isfinite(kt)) continue;
        const double dem = pt.value(q.c_str());
        const double deviation = kt != 0.0 ? (dem - kt) / kt : NAN;
        csv << pt.solidFraction << ',' << pt.restitution << ',' << pt.friction << ',' << pt.shearRate << ',' << q << ','
            << dem << ',' << pt.error(q) << ',' << kt::toString(model) << ',' << kt << ',' << deviation << '\n';
        if (model == primary && pt.solidFraction <= limit && std::isfinite(deviation)) {
          worst[q] = std::max(worst[q], std::abs(deviation));
        }
      }
    }
  }
  core::writeFileAtomically(ctx.outputDir() / "comparison.csv", csv.str());
  ctx.addArtifact("comparison.csv", "csv");
  for (const auto& [q, w] : worst) summary["max_abs_deviation_" + q] = w;

  // Plots: per quantity, DEM points (error bars) per (e, mu) and each model's curve per e.
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>"
       << core::io::xmlEscape(p.at("title").get<std::string>())
       << "</title></head><body style=\"font-family:sans-serif\">\n<h1>"
       << core::io::xmlEscape(p.at("title").get<std::string>())
       << "</h1>\n<p>DEM closure points (symbols, with block-averaging errors) against kinetic theory (lines: "
       << "lun1984 solid, the algebraic forms dashed) at the same solid fraction and restitution. Relative "
       << "deviations of every model: <a href=\"comparison.csv\">comparison.csv</a>. Summary model: "
       << kt::toString(primary) << ".</p>\n";
  std::set<double> restitutions;
  for (const auto& pt : points) restitutions.insert(pt.restitution);
  const Point& ref = points.front();
  for (const auto& q : quantities) {
    report::Figure fig;
    fig.title = quantityLabels().at(q);
    fig.xLabel = "solid fraction";
    fig.yLabel = q;
    fig.logY = true;
    std::map<std::pair<double, double>, report::FigureSeries> dem;
    for (const auto& pt : points) {
      if (!pt.has(q.c_str())) continue;
      auto& s = dem[{pt.restitution, pt.friction}];
      std::ostringstream label;
      label << "DEM e=" << pt.restitution << " mu=" << pt.friction;
      s.label = label.str();
      s.style = report::FigureSeries::Style::PointsWithErrors;
      s.x.push_back(pt.solidFraction);
      s.y.push_back(pt.value(q.c_str()));
      s.yError.push_back(pt.error(q));
    }
    if (dem.empty()) continue;
    for (auto& [k, s] : dem) fig.series.push_back(std::move(s));
    const double shearRate = ref.shearRate;
    for (double e : restitutions) {
      for (auto model : kt::kAllKineticModels) {
        report::FigureSeries curve;
        std::ostringstream label;
        label << kt::toString(model) << " e=" << e;
        curve.label = label.str();
        curve.style = model == kt::KineticModelName::Lun1984 ? report::FigureSeries::Style::Line
                                                             : report::FigureSeries::Style::DashedLine;
        for (double eps = 0.02; eps <= 0.6001; eps += 0.01) {
          const double v = predicted(predict(model, eps, e, shearRate, ref.diameter, ref.density), q);
          if (std::isfinite(v) && v > 0.0) {
            curve.x.push_back(eps);
            curve.y.push_back(v);
          }
        }
        fig.series.push_back(std::move(curve));
      }
    }
    const std::string name = "compare_" + q + ".svg";
    report::drawSvg(fig, ctx.outputDir() / name);
    ctx.addArtifact(name, "svg");
    html << "<img src=\"" << name << "\" alt=\"" << core::io::xmlEscape(fig.title) << "\">\n";
  }
  html << "</body></html>\n";
  core::writeFileAtomically(ctx.outputDir() / "compare.html", html.str());
  ctx.addArtifact("compare.html", "report_html");
  ctx.setSummary(summary);
}

}  // namespace grainbridge::workflows::stages
