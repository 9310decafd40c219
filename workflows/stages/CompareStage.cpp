#include "workflows/stages/CompareStage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "core/ClosureForms.hpp"
#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/Log.hpp"
#include "core/io/XdmfText.hpp"
#include "core/text/NumberText.hpp"
#include "engines/closures/KineticModel.hpp"
#include "extract/statistics/InertialRheologyFit.hpp"
#include "workflows/report/Plot.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;
using params::ParamSpec;
namespace kt = grainbridge::closures;

CompareStage::CompareStage() {
  schema_
      .add(ParamSpec::string("model")
               .defaultValue("lun1984")
               .options({"lun1984", "lun1984_mfix", "syamlal_algebraic", "syamlal_algebraic_mfix"})
               .doc("the model the summary's deviations refer to (every model is in the CSV and plots)"))
      .add(ParamSpec::number("summary_max_solid_fraction")
               .defaultValue(0.2)
               .min(0.0)
               .doc("the summary's largest deviation is over points up to this solid fraction"))
      .add(ParamSpec::number("fit_inertial_number_max")
               .defaultValue(0.5)
               .positive()
               .doc("the mu(I) and phi(I) figures fit the points with inertial number up to this (as tabulate "
                    "does)"))
      .add(ParamSpec::string("title").defaultValue("DEM closures against kinetic theory").doc("page title"));
}

namespace {

// One DEM closure point, from an extract instance's summary.
struct Point {
  std::string key;
  double solidFraction = 0, restitution = 1, friction = 0, shearRate = 0, diameter = 0, density = 0;
  bool ordered = false;  // its box crystallised (issue 61): drawn apart, left out of bands and fits
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

std::string percent(double relative) {
  // Three significant digits, but never an exponent: a 1040 % deviation reads as such.
  const double pct = std::abs(100.0 * relative);
  const std::string digits =
      pct >= 100.0 ? std::to_string(static_cast<long long>(std::lround(pct))) : core::humanNumber(pct, 3);
  return (relative >= 0 ? "+" : "−") + digits + " %";
}

std::string where(const Point& pt) {
  return "φ " + core::humanNumber(pt.solidFraction, 3) + ", e " + core::humanNumber(pt.restitution) +
         (pt.friction != 0.0 ? ", μ " + core::humanNumber(pt.friction) : "");
}

// One finite relative deviation of a closure point from a model, as comparison.csv has it.
struct Deviation {
  double relative = 0.0;  // (DEM - model) / model
  const Point* at = nullptr;
  std::string quantity;
  kt::KineticModelName model = kt::KineticModelName::Lun1984;
};

// The findings' headline and table: for each model and form its largest relative deviation
// from DEM and the state where it occurs; the sentence names the primary model's largest,
// over every point and over the dilute points the summary is restricted to.
void describeDeviations(const std::vector<Point>& points, const std::vector<std::string>& quantities,
                        const std::vector<Deviation>& deviations, kt::KineticModelName primary, double limit,
                        contract::Findings& findings) {
  std::vector<std::string> present;
  for (const auto& q : quantities) {
    if (std::any_of(points.begin(), points.end(), [&](const Point& pt) { return pt.has(q.c_str()); }))
      present.push_back(q);
  }
  findings.columns = {"largest deviation from"};
  for (const auto& q : present)
    findings.columns.emplace_back(core::closureFormInfo(*core::closureFormFromName(q)).symbol);
  Deviation primaryAll, primaryDilute;
  for (auto model : kt::kAllKineticModels) {
    std::vector<std::string> row = {std::string(kt::toString(model))};
    for (const auto& q : present) {
      Deviation worst;
      for (const auto& d : deviations) {
        if (d.model != model || d.quantity != q) continue;
        const Point& pt = *d.at;
        if (worst.at == nullptr || std::abs(d.relative) > std::abs(worst.relative)) worst = d;
        if (model == primary) {
          if (primaryAll.at == nullptr || std::abs(d.relative) > std::abs(primaryAll.relative)) primaryAll = d;
          if (pt.solidFraction <= limit &&
              (primaryDilute.at == nullptr || std::abs(d.relative) > std::abs(primaryDilute.relative)))
            primaryDilute = d;
        }
      }
      row.push_back(worst.at == nullptr ? "–" : percent(worst.relative) + " (" + where(*worst.at) + ")");
    }
    findings.rows.push_back(std::move(row));
  }
  auto [loPhi, hiPhi] = std::minmax_element(
      points.begin(), points.end(), [](const Point& a, const Point& b) { return a.solidFraction < b.solidFraction; });
  std::ostringstream h;
  h << points.size() << " DEM closure point" << (points.size() == 1 ? "" : "s") << " (φ "
    << core::humanNumber(loPhi->solidFraction, 3);
  if (hiPhi->solidFraction != loPhi->solidFraction) h << "–" << core::humanNumber(hiPhi->solidFraction, 3);
  h << ").";
  auto symbol = [](const std::string& q) {
    return std::string(core::closureFormInfo(*core::closureFormFromName(q)).symbol);
  };
  if (primaryAll.at != nullptr) {
    h << " Largest deviation from " << kt::toString(primary) << ": " << percent(primaryAll.relative) << " in "
      << symbol(primaryAll.quantity) << " at " << where(*primaryAll.at) << ".";
  }
  if (primaryDilute.at != nullptr && primaryDilute.at != primaryAll.at) {
    h << " Up to φ " << core::humanNumber(limit) << ": " << percent(primaryDilute.relative) << " in "
      << symbol(primaryDilute.quantity) << " at " << where(*primaryDilute.at) << ".";
  }
  h << " Deviation = (DEM − model) / model; all forms dimensionless.";
  findings.headline = h.str();
}

// One kinetic theory's curve at restitution e, one point per solid fraction 0.02..0.60 where
// `at` gives one ((x, y) from the model's prediction there); dash `variant` tells the e apart.
report::Series kineticTheoryCurve(kt::KineticModelName model, double e, int variant,
                                  const std::function<std::optional<std::pair<double, double>>(double eps)>& at) {
  report::Series curve;
  curve.label = std::string(kt::toString(model)) + ", e " + core::humanNumber(e);
  curve.model = kt::toString(model);
  curve.style = report::Series::Style::Line;
  curve.variant = variant;
  for (double eps = 0.02; eps <= 0.6001; eps += 0.01) {
    if (const auto xy = at(eps)) {
      curve.x.push_back(xy->first);
      curve.y.push_back(xy->second);
    }
  }
  return curve;
}

// A DEM series' label: its restitution and, when not zero, its friction.
std::string demLabel(const Point& pt) {
  return "DEM, e " + core::humanNumber(pt.restitution) +
         (pt.friction != 0.0 ? ", μ " + core::humanNumber(pt.friction) : "");
}

// The points whose box ordered, whatever their state, in grey: shown, and left out of the table
// bands and the fits as tabulate leaves them out (issue 61).
report::Series orderedSeries() {
  report::Series s;
  s.label = "DEM, box ordered (left out of table and fits)";
  s.model = "DEM";
  s.style = report::Series::Style::PointsWithErrors;
  s.variant = 5;
  s.colour = "#888888";
  return s;
}

// One fitted relation's legend entry: its parameters with their errors and its chi2/dof.
std::string fitLabel(const extract::statistics::RheologyFit& fit, double restitution) {
  namespace st = extract::statistics;
  static const std::map<std::string, std::string> symbols = {
      {"mu_s", "μs"},        {"mu_2", "μ2"},         {"inertial_number_0", "I0"}, {"phi_c", "φc"},
      {"slope", "a"},        {"mu_c", "μc"},         {"mu_amplitude", "B"},       {"mu_exponent", "b"},
      {"phi_c_power", "φc"}, {"phi_amplitude", "A"}, {"phi_exponent", "a"}};
  const char* form = "";
  switch (fit.relation) {
    case st::RheologyRelation::MuOfI:
      form = "μs + (μ2 − μs)/(1 + I0/I)";
      break;
    case st::RheologyRelation::PhiOfI:
      form = "φc − a I";
      break;
    case st::RheologyRelation::MuOfIPower:
      form = "μc + B I^b";
      break;
    case st::RheologyRelation::PhiOfIPower:
      form = "φc − A I^a";
      break;
  }
  std::string label = std::string("fit ") + form + ", e " + core::humanNumber(restitution) + ":";
  for (std::size_t k = 0; k < fit.names.size(); ++k) {
    const auto sym = symbols.find(fit.names[k]);
    label += (k == 0 ? " " : ", ") + (sym != symbols.end() ? sym->second : fit.names[k]) + " " +
             core::humanNumber(fit.params[static_cast<Eigen::Index>(k)], 3) + " ± " +
             core::humanNumber(fit.errors[static_cast<Eigen::Index>(k)], 1);
  }
  return label + ", χ²/dof " + core::humanNumber(fit.chi2PerDof, 3);
}

// The dense-flow rheology (Chialvo, Sun and Sundaresan 2012): the stress ratio mu = tau / p and
// the solid fraction against the inertial number I, DEM points per (e, friction) with their fits
// (extract/statistics/InertialRheologyFit, points with I <= fitMax, ordered boxes left out): Jop's
// mu(I) and the linear phi(I) beside the power laws near the critical point (issue 61), each
// labelled with its chi2/dof; and each kinetic theory's steady simple shear, where
// I = 1 / sqrt(p*) and mu = tau* / p* depend on (phi, e) only.
std::vector<report::Figure> rheologyFigures(const std::vector<Point>& points, const std::set<double>& restitutions,
                                            double fitMax) {
  namespace st = extract::statistics;
  std::vector<report::Figure> figures;
  for (const bool mu : {true, false}) {
    const std::array relations = mu ? std::array{st::RheologyRelation::MuOfI, st::RheologyRelation::MuOfIPower}
                                    : std::array{st::RheologyRelation::PhiOfI, st::RheologyRelation::PhiOfIPower};
    report::Figure fig;
    fig.title = mu ? "Stress ratio against inertial number" : "Solid fraction against inertial number";
    fig.x = {"inertial number I", "–", true};
    fig.y = mu ? report::Axis{"μ = τ/p", "–", false} : report::Axis{"solid fraction φ", "–", false};
    std::map<std::pair<double, double>, std::pair<report::Series, std::vector<st::RheologySample>>> dem;
    report::Series ordered = orderedSeries();
    double lowest = std::numeric_limits<double>::infinity(), highest = 0.0;
    for (const auto& pt : points) {
      if (!pt.has("inertial_number") || !pt.has("stress_ratio")) continue;
      const double I = pt.value("inertial_number");
      const double y = mu ? pt.value("stress_ratio") : pt.solidFraction;
      const double yErr = pt.error(mu ? "stress_ratio" : "solid_fraction");
      lowest = std::min(lowest, I);
      highest = std::max(highest, I);
      if (pt.ordered) {
        ordered.x.push_back(I);
        ordered.y.push_back(y);
        ordered.yError.push_back(yErr);
        continue;
      }
      auto& [s, samples] = dem[{pt.restitution, pt.friction}];
      s.label = demLabel(pt);
      s.model = "DEM";
      s.style = report::Series::Style::PointsWithErrors;
      s.x.push_back(I);
      s.y.push_back(y);
      s.yError.push_back(yErr);
      if (I <= fitMax) samples.push_back({I, pt.error("inertial_number"), y, yErr});
    }
    if (dem.empty() && ordered.x.empty()) return {};
    int variant = 0;
    for (auto& [state, entry] : dem) {
      auto& [s, samples] = entry;
      s.variant = variant;
      fig.series.push_back(std::move(s));
      for (std::size_t form = 0; form < relations.size(); ++form) {
        try {
          const auto fit = st::fitRheology(relations[form], samples);
          report::Series fitted;
          fitted.label = fitLabel(fit, state.first);
          fitted.model = "DEM";
          fitted.style = report::Series::Style::Line;
          fitted.variant = variant + static_cast<int>(form);
          double from = samples.front().inertialNumber, to = from;
          for (const auto& x : samples) from = std::min(from, x.inertialNumber), to = std::max(to, x.inertialNumber);
          for (int k = 0; k <= 60; ++k) {
            const double I = from * std::pow(to / from, k / 60.0);
            fitted.x.push_back(I);
            fitted.y.push_back(fit(I));
          }
          fig.series.push_back(std::move(fitted));
        } catch (const Error&) {
          // Too few points below the cap, or points that do not determine the law: no line.
        }
      }
      variant += static_cast<int>(relations.size());
    }
    if (!ordered.x.empty()) fig.series.push_back(std::move(ordered));
    int eIndex = 0;
    for (double e : restitutions) {
      for (auto model : kt::kAllKineticModels) {
        auto curve = kineticTheoryCurve(model, e, eIndex, [&](double eps) -> std::optional<std::pair<double, double>> {
          const Point& ref = points.front();
          const auto pred = predict(model, eps, e, ref.shearRate, ref.diameter, ref.density);
          const double I = 1.0 / std::sqrt(pred.pShear);
          // Kinetic theory's I spans decades; draw it over the DEM points' range only.
          if (!std::isfinite(I) || I < 0.5 * lowest || I > 2.0 * highest) return std::nullopt;
          return std::pair{I, mu ? pred.tauShear / pred.pShear : eps};
        });
        if (!curve.x.empty()) fig.series.push_back(std::move(curve));
      }
      ++eIndex;
    }
    figures.push_back(std::move(fig));
  }
  return figures;
}

}  // namespace

void CompareStage::checkAgainstUpstream(const json& /*p*/, const std::string& ptr,
                                        const std::vector<UpstreamPlan>& upstream, core::json::Diagnostics& d) const {
  if (const auto* up = withoutClosurePoint(upstream)) {
    d.add(ptr, "upstream stage " + up->stage + " records no closure point: compare takes stages that do (extract)");
  }
}

void CompareStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  const auto primary = kt::kineticModelFromString(p.at("model").get<std::string>());
  std::vector<Point> points;
  for (const auto& up : ctx.inputs()) {
    // What compare needs is a closure point, whichever stage computed it.
    if (up.records("closure_points").empty()) {
      throw Error("compare: upstream " + up.stage() + " (" + up.shortKey() +
                  ") recorded no closure point; compare takes stages that do (extract)");
    }
    Point pt;
    pt.key = up.key();
    pt.summary = up.summary();
    pt.solidFraction = pt.value("solid_fraction");
    pt.diameter = pt.value("diameter");
    pt.density = pt.value("density");
    if (!pt.has("restitution")) {
      throw Error("compare: the closure point of " + up.stage() + " (" + up.shortKey() +
                  ") has no restitution: its particle frames carry no contact materials");
    }
    pt.restitution = pt.value("restitution");
    pt.friction = pt.has("friction") ? pt.value("friction") : 0.0;
    pt.shearRate = pt.has("shear_rate") ? pt.value("shear_rate") : 0.0;
    pt.ordered = pt.has("ordered") && pt.value("ordered") != 0.0;
    points.push_back(std::move(pt));
  }
  if (points.empty()) throw Error("compare: no upstream closure points; give it \"from\"");
  std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) {
    return std::tie(a.restitution, a.friction, a.solidFraction) < std::tie(b.restitution, b.friction, b.solidFraction);
  });

  const std::vector<std::string> quantities = {"p_shear", "tau_shear", "t_shear", "p_theta", "eta_theta", "j_theta"};
  std::ostringstream csv;
  csv.precision(std::numeric_limits<double>::max_digits10);  // full precision: a CSV is read back by programs
  // The state identifies the point; which extract run it came from is in the database
  // (run_inputs), not here, so the CSV does not change when an upstream key does.
  csv << "solid_fraction,restitution,friction,shear_rate,quantity,dem,dem_err,model,prediction,deviation\n";
  json summary = {
      {"model", kt::toString(primary)},
      {"points", points.size()},
      {"ordered_points", std::count_if(points.begin(), points.end(), [](const Point& pt) { return pt.ordered; })}};
  const double limit = p.at("summary_max_solid_fraction");
  std::map<std::string, double> worst;
  std::vector<Deviation> deviations;  // the finite ones, for the findings
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
        if (!std::isfinite(deviation)) continue;
        deviations.push_back({deviation, &pt, q, model});
        if (model == primary && pt.solidFraction <= limit) worst[q] = std::max(worst[q], std::abs(deviation));
      }
    }
  }
  core::writeFileAtomically(ctx.outputDir() / "comparison.csv", csv.str());
  ctx.addArtifact("comparison.csv", "csv");
  for (const auto& [q, w] : worst) summary["max_abs_deviation_" + q] = w;

  // Figures: per quantity, DEM points (block-averaging error bars) per (e, mu) and each
  // model's curve per e, shear-scaled forms first (what a simple-shear sweep is about).
  std::set<double> restitutions;
  for (const auto& pt : points) restitutions.insert(pt.restitution);
  const Point& ref = points.front();
  contract::Findings findings;
  findings.title = p.at("title").get<std::string>();
  findings.details = "compare.html";
  for (const auto& q : quantities) {
    const auto& form = core::closureFormInfo(*core::closureFormFromName(q));
    report::Figure fig;
    fig.title = std::string(form.label);
    fig.x = {"solid fraction φ", "–"};
    fig.y = {std::string(form.symbol), "–", true};
    std::map<std::pair<double, double>, report::Series> dem;
    report::Series ordered = orderedSeries();
    for (const auto& pt : points) {
      if (!pt.has(q.c_str())) continue;
      auto& s = pt.ordered ? ordered : dem[{pt.restitution, pt.friction}];
      if (!pt.ordered) {
        s.label = demLabel(pt);
        s.model = "DEM";
        s.style = report::Series::Style::PointsWithErrors;
      }
      s.x.push_back(pt.solidFraction);
      s.y.push_back(pt.value(q.c_str()));
      s.yError.push_back(pt.error(q));
    }
    if (dem.empty() && ordered.x.empty()) continue;
    int variant = 0;
    for (auto& [k, s] : dem) {
      s.variant = variant++;
      // The table tabulate makes of these points, with its errors (issue 31): a band joining each
      // node's value ± one standard error. On the log axis a band reaching zero stops at a tenth
      // of the value.
      if (s.x.size() >= 2) {
        std::vector<std::size_t> order(s.x.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.x[a] < s.x[b]; });
        report::Series band;
        band.label = s.label + ", table ± 1 standard error";
        band.model = "DEM";
        band.style = report::Series::Style::Band;
        band.variant = s.variant;
        for (const std::size_t i : order) {
          const double hi = s.y[i] + s.yError[i];
          const double lo = std::max(s.y[i] - s.yError[i], 0.1 * s.y[i]);
          band.x.push_back(s.x[i]);
          band.y.push_back(0.5 * (hi + lo));
          band.yError.push_back(0.5 * (hi - lo));
        }
        fig.series.push_back(std::move(band));
      }
      fig.series.push_back(std::move(s));
    }
    if (!ordered.x.empty()) fig.series.push_back(std::move(ordered));
    const double shearRate = ref.shearRate;
    int eIndex = 0;
    for (double e : restitutions) {
      for (auto model : kt::kAllKineticModels) {
        fig.series.push_back(
            kineticTheoryCurve(model, e, eIndex, [&](double eps) -> std::optional<std::pair<double, double>> {
              const double v = predicted(predict(model, eps, e, shearRate, ref.diameter, ref.density), q);
              if (!(std::isfinite(v) && v > 0.0)) return std::nullopt;
              return std::pair{eps, v};
            }));
      }
      ++eIndex;
    }
    const auto drawn = report::drawFigure(fig, ctx.outputDir(), "compare_" + q);
    ctx.addArtifact(drawn.svg, "svg");
    ctx.addArtifact(drawn.png, "png");
    findings.figures.push_back({drawn.svg, drawn.png, fig.title});
  }
  const auto rheology = rheologyFigures(points, restitutions, p.at("fit_inertial_number_max").get<double>());
  for (std::size_t k = 0; k < rheology.size(); ++k) {
    const auto drawn = report::drawFigure(rheology[k], ctx.outputDir(), k == 0 ? "compare_mu_of_I" : "compare_phi_of_I");
    ctx.addArtifact(drawn.svg, "svg");
    ctx.addArtifact(drawn.png, "png");
    findings.figures.push_back({drawn.svg, drawn.png, rheology[k].title});
  }
  // Shear-scaled forms first; the first screen shows the three of one family.
  std::stable_partition(findings.figures.begin(), findings.figures.end(),
                        [](const contract::FindingsFigure& f) { return f.svg.find("_shear") != std::string::npos; });
  describeDeviations(points, quantities, deviations, primary, limit, findings);
  ctx.setFindings(findings);

  std::ostringstream html;
  const std::string title = core::io::xmlEscape(findings.title);
  html
      << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" << title
      << "</title><style>body{font-family:sans-serif;margin:1.5em;max-width:80em}img{width:32%;min-width:20em}"
      << "</style></head><body>\n<h1>" << title << "</h1>\n<p>" << core::io::xmlEscape(findings.headline)
      << "</p>\n<p>DEM closure points (symbols, with block-averaging errors) against kinetic theory (lines, one colour "
      << "per model, one dash per restitution) at the same solid fraction and restitution. Every model's relative "
      << "deviations: <a href=\"comparison.csv\">comparison.csv</a>. PNG copies for slides sit beside each SVG.</p>\n";
  for (const auto& f : findings.figures) {
    html << "<a href=\"" << f.png << "\"><img src=\"" << f.svg << "\" alt=\"" << core::io::xmlEscape(f.caption)
         << "\"></a>\n";
  }
  html << "</body></html>\n";
  core::writeFileAtomically(ctx.outputDir() / "compare.html", html.str());
  ctx.addArtifact("compare.html", "report_html");
  ctx.setSummary(summary);
}

}  // namespace grainbridge::workflows::stages
