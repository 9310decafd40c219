#include "workflows/stages/MixtureCompareStage.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/text/NumberText.hpp"
#include "engines/closures/EffectiveRestitution.hpp"
#include "engines/closures/GhdTemperatureRatio.hpp"
#include "engines/closures/MixtureSimpleShear.hpp"
#include "workflows/report/Plot.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;
using params::ParamSpec;
namespace kt = grainbridge::closures;

MixtureCompareStage::MixtureCompareStage() {
  schema_
      .add(ParamSpec::string("model")
               .defaultValue("lun1984")
               .options({"lun1984", "lun1984_mfix"})
               .doc("the kinetic model whose mixture forms are compared (the models that read the mixture sums)"))
      .add(ParamSpec::boolean("rotation_model")
               .defaultValue(false)
               .doc("the particle-rotation model's effective restitution in each phase's dissipation (Eqs. "
                    "5.11-5.20, from the boxes' friction), as mfm's rotation_model; frictionless boxes are "
                    "unaffected"))
      .add(ParamSpec::number("tangential_restitution")
               .defaultValue(0.33)
               .min(-1.0)
               .max(1.0)
               .doc("beta0 of the rotation model (Eq. 5.17; Table 5.1's 0.33)"))
      .add(ParamSpec::string("title")
               .defaultValue("A mixture's DEM closures against mixture kinetic theory")
               .doc("page title"));
}

namespace {

struct Measured {
  double value = NAN, error = 0.0;
};

struct SpeciesPoint {
  std::string name;
  double share = 0, diameter = 0, density = 0, restitution = 1, friction = 0;
  Measured temperature, pressure, kineticPressure, shearStress, dissipation;
};

// One sheared box: its species and what needs no attribution to them.
struct Box {
  std::string stage;
  double mixtureFraction = 0, shearRate = 0;
  std::vector<SpeciesPoint> species;
  Measured temperatureRatio, collisionalPressure, dissipation;
};

json extraOf(const json& row) {
  if (!row.contains("extra_json")) return json::object();
  const json& e = row["extra_json"];
  return e.is_string() ? json::parse(e.get<std::string>()) : e;
}

Measured measured(const json& row, const std::string& key) {
  if (!row.contains(key) || !row[key].is_number()) return {};
  const std::string err = key + "_err";
  return {row[key].get<double>(), row.contains(err) && row[err].is_number() ? row[err].get<double>() : 0.0};
}

Box boxOf(const UpstreamInstance& up) {
  Box box;
  box.stage = up.stage() + " (" + up.shortKey() + ")";
  const auto rows = up.records("closure_points");
  std::vector<json> pairs;
  for (const json& row : rows) {
    const std::string species = row.value("species", std::string("all"));
    if (species == "all") {
      box.dissipation = measured(row, "dissipation_rate");
    } else if (row.contains("volume_share") && row["volume_share"].is_number()) {
      SpeciesPoint s;
      s.name = species;
      s.share = row["volume_share"].get<double>();
      s.diameter = row.at("diameter").get<double>();
      s.density = row.at("density").get<double>();
      s.restitution = row.value("restitution", 1.0);
      s.friction = row.value("friction", 0.0);
      s.temperature = measured(row, "granular_temperature");
      s.pressure = measured(row, "pressure");
      s.shearStress = measured(row, "shear_stress");
      const json extra = extraOf(row);
      s.kineticPressure = measured(extra, "pressure_kinetic");
      s.dissipation = measured(row, "dissipation_rate");
      box.mixtureFraction = row.at("mixture_solid_fraction").get<double>();
      if (row.contains("shear_rate")) box.shearRate = row["shear_rate"].get<double>();
      box.species.push_back(std::move(s));
    } else {
      pairs.push_back(row);
    }
  }
  if (box.species.size() < 2) {
    throw Error("compare_mixture: upstream " + box.stage +
                " recorded no species closure points: it needs frames of a mixture (two species or more)");
  }
  if (!(box.shearRate > 0.0)) {
    throw Error("compare_mixture: upstream " + box.stage +
                " is not sheared (no shear_rate): the comparison is of steady simple shear");
  }
  double collisional = 0.0, variance = 0.0;
  for (const json& row : pairs) {
    const Measured p = measured(row, "pressure");
    collisional += p.value;
    variance += p.error * p.error;  // the pairs' errors as if independent: an estimate
    if (row["species"] == box.species[0].name + "+" + box.species[1].name) {
      box.temperatureRatio = measured(extraOf(row), "temperature_ratio");
    }
  }
  box.collisionalPressure = {collisional, std::sqrt(variance)};
  return box;
}

struct Form {
  kt::MixtureKineticTheory form;
  const char* name;
  const char* colour;
};
constexpr Form kForms[] = {{kt::MixtureKineticTheory::Summed, "summed", "#0072B2"},
                           {kt::MixtureKineticTheory::PerPhase, "per_phase", "#D55E00"}};

// The theory a box is compared with: the kinetic model, and the rotation model's effective
// restitution in the dissipation when asked for.
struct Theory {
  kt::KineticModelName model = kt::KineticModelName::Lun1984;
  bool rotation = false;
  double tangentialRestitution = 0.33;
  // e_eff of a species (Eq. 5.19) under the rotation model, else its e.
  [[nodiscard]] double effectiveRestitution(const SpeciesPoint& s) const {
    return rotation ? kt::EffectiveRestitution{{s.friction, tangentialRestitution}}
                          .evaluate(s.restitution)
                          .effectiveRestitution
                    : s.restitution;
  }
};

// The prediction at a box's composition, scaled to `mixtureFraction` (the curves).
std::vector<kt::ShearedPhaseState> predictAt(const Theory& theory, kt::MixtureKineticTheory form, const Box& box,
                                             double mixtureFraction) {
  std::vector<kt::ShearedPhase> phases;
  for (const SpeciesPoint& s : box.species) {
    kt::ShearedPhase phase{mixtureFraction * s.share, s.diameter, s.density, s.restitution};
    const double elastic = 1.0 - s.restitution * s.restitution;
    if (theory.rotation && elastic > 0.0) {
      // Eq. 5.20 over Eq. 5.7, as mfm scales each phase's dissipation.
      phase.dissipationScale = (1.0 + s.restitution) * (1.0 - theory.effectiveRestitution(s)) / elastic;
    }
    phases.push_back(phase);
  }
  return kt::mixtureSimpleShear(theory.model, form, phases, box.shearRate);
}

// theta_0 / theta_1 (per unit mass) of Garzo, Hrenya and Dufty's zeroth order at the box's
// composition scaled to `mixtureFraction`, with the first species' restitution (its effective
// one under the rotation model) for every pair.
double ghdThetaRatio(const Theory& theory, const Box& box, double mixtureFraction) {
  std::vector<kt::CoolingSpecies> two;
  for (std::size_t m = 0; m < 2; ++m) {
    const SpeciesPoint& s = box.species[m];
    two.push_back({mixtureFraction * s.share, s.diameter, s.density});
  }
  const double massRatio = box.species[1].density * std::pow(box.species[1].diameter, 3) /
                           (box.species[0].density * std::pow(box.species[0].diameter, 3));
  return kt::ghdTemperatureRatio(two, theory.effectiveRestitution(box.species[0])) * massRatio;
}
constexpr const char* kGhdColour = "#009E73";

// A compared quantity: of a species (its index) or of the box (species < 0), in shear units of the
// first species (rho_0 d_0^2 gammadot^2 for stresses, (d gammadot)^2 for temperatures).
struct Quantity {
  std::string key, label;
  int species;
  double unit;  // SI value over this = shear units
  Measured dem;
  double (*predicted)(const std::vector<kt::ShearedPhaseState>&, int species);
};

std::vector<Quantity> quantitiesOf(const Box& box) {
  const SpeciesPoint& first = box.species[0];
  const double g2 = box.shearRate * box.shearRate;
  const double stress0 = first.density * first.diameter * first.diameter * g2;
  std::vector<Quantity> out;
  // theta = <C^2>/3 per unit mass, as the multi-fluid model's: equal energies per grain would give
  // theta_0 / theta_1 = m_1 / m_0.
  out.push_back({"temperature_ratio", "θ_" + first.name + " / θ_" + box.species[1].name, -1, 1.0, box.temperatureRatio,
                 [](const auto& p, int) { return p[0].granularTemperature / p[1].granularTemperature; }});
  for (std::size_t m = 0; m < box.species.size(); ++m) {
    const SpeciesPoint& s = box.species[m];
    const double stress = s.density * s.diameter * s.diameter * g2;
    const int i = static_cast<int>(m);
    out.push_back({"t_shear_" + s.name, "T* of " + s.name, i, s.diameter * s.diameter * g2, s.temperature,
                   [](const auto& p, int k) { return p[static_cast<std::size_t>(k)].granularTemperature; }});
    out.push_back({"p_shear_" + s.name, "p* of " + s.name, i, stress, s.pressure,
                   [](const auto& p, int k) { return p[static_cast<std::size_t>(k)].pressure; }});
    out.push_back({"p_kinetic_shear_" + s.name, "kinetic p* of " + s.name, i, stress, s.kineticPressure,
                   [](const auto& p, int k) { return p[static_cast<std::size_t>(k)].kineticPressure; }});
    out.push_back({"tau_shear_" + s.name, "τ* of " + s.name, i, stress, s.shearStress,
                   [](const auto& p, int k) { return p[static_cast<std::size_t>(k)].shearStress; }});
    // The species' J, the shear work on its partial stress (its net collisional loss): the
    // model's J_m, which in its own balance equals its shear work too.
    out.push_back({"j_shear_" + s.name, "J* of " + s.name, i, stress * box.shearRate, s.dissipation,
                   [](const auto& p, int k) { return p[static_cast<std::size_t>(k)].dissipationRate; }});
  }
  out.push_back({"p_collisional_shear", "collisional p* (all pairs)", -1, stress0, box.collisionalPressure,
                 [](const auto& p, int) {
                   double sum = 0.0;
                   for (const auto& s : p) sum += s.pressure - s.kineticPressure;
                   return sum;
                 }});
  out.push_back({"j_shear", "J* (all pairs)", -1, stress0 * box.shearRate, box.dissipation, [](const auto& p, int) {
                   double sum = 0.0;
                   for (const auto& s : p) sum += s.dissipationRate;
                   return sum;
                 }});
  return out;
}

// A mean |ln(DEM / model)| as the factor it stands for.
std::string factor(double meanAbsLog) { return "×" + core::humanNumber(std::exp(meanAbsLog), 3); }

}  // namespace

void MixtureCompareStage::checkAgainstUpstream(const json& /*p*/, const std::string& ptr,
                                               const std::vector<UpstreamPlan>& upstream,
                                               core::json::Diagnostics& d) const {
  if (const auto* up = withoutClosurePoint(upstream)) {
    d.add(ptr, "upstream stage " + up->stage +
                   " records no closure point: compare_mixture takes stages that do (extract of a mixture)");
  }
}

void MixtureCompareStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  const auto model = kt::kineticModelFromString(p.at("model").get<std::string>());
  const Theory theory{model, p.at("rotation_model").get<bool>(), p.at("tangential_restitution").get<double>()};
  std::vector<Box> boxes;
  for (const auto& up : ctx.inputs()) boxes.push_back(boxOf(up));
  if (boxes.empty()) throw Error("compare_mixture: no upstream closure points; give it \"from\"");
  std::sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) {
    return std::tie(a.species[0].restitution, a.species[0].share, a.mixtureFraction) <
           std::tie(b.species[0].restitution, b.species[0].share, b.mixtureFraction);
  });

  std::ostringstream csv;
  csv.precision(std::numeric_limits<double>::max_digits10);
  csv << "mixture_solid_fraction,volume_share_first,restitution,shear_rate,quantity,dem,dem_err,form,prediction,"
         "deviation\n";
  // Per quantity kind (key without the species) and form: the relative deviations, for the findings.
  std::map<std::string, std::map<std::string, std::vector<double>>> deviations;
  std::map<std::string, std::string> labels;
  std::vector<double> ghdDeviations;
  for (const Box& box : boxes) {
    for (const Form& f : kForms) {
      const auto pred = predictAt(theory, f.form, box, box.mixtureFraction);
      for (const Quantity& q : quantitiesOf(box)) {
        if (!std::isfinite(q.dem.value)) continue;
        const double kt = q.predicted(pred, q.species);
        const double deviation = kt != 0.0 ? (q.dem.value - kt) / kt : NAN;
        // In shear units, as the quantity's name says (the deviation is the same in any unit).
        csv << box.mixtureFraction << ',' << box.species[0].share << ',' << box.species[0].restitution << ','
            << box.shearRate << ',' << q.key << ',' << q.dem.value / q.unit << ',' << q.dem.error / q.unit << ','
            << f.name << ',' << kt / q.unit << ',' << deviation << '\n';
        // The findings weigh over- and under-prediction alike: |ln(DEM / model)|, a factor.
        if (q.dem.value > 0.0 && kt > 0.0) {
          deviations[q.key][f.name].push_back(std::abs(std::log(q.dem.value / kt)));
          labels[q.key] = q.label;
        }
      }
    }
    // The temperature ratio by a theory that exchanges energy between species (GHD's zeroth
    // order): the one quantity it is compared on here.
    if (std::isfinite(box.temperatureRatio.value) && box.species.size() == 2) {
      const double kt = ghdThetaRatio(theory, box, box.mixtureFraction);
      csv << box.mixtureFraction << ',' << box.species[0].share << ',' << box.species[0].restitution << ','
          << box.shearRate << ",temperature_ratio," << box.temperatureRatio.value << ',' << box.temperatureRatio.error
          << ",ghd," << kt << ',' << (box.temperatureRatio.value - kt) / kt << '\n';
      ghdDeviations.push_back(std::abs(std::log(box.temperatureRatio.value / kt)));
    }
  }
  core::writeFileAtomically(ctx.outputDir() / "mixture_comparison.csv", csv.str());
  ctx.addArtifact("mixture_comparison.csv", "csv");

  // Findings: per quantity, each form's mean |deviation| over the boxes; the headline counts
  // where each form is the closer one.
  contract::Findings findings;
  findings.title = p.at("title").get<std::string>();
  findings.columns = {"quantity", "boxes", "summed: off by ×", "per_phase: off by ×", "closer"};
  std::map<std::string, int> wins;
  double summedAll = 0.0, perPhaseAll = 0.0;
  std::size_t all = 0;
  const auto mean = [](const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return v.empty() ? NAN : s / static_cast<double>(v.size());
  };
  for (const auto& [key, byForm] : deviations) {
    const auto s = byForm.find("summed"), pp = byForm.find("per_phase");
    if (s == byForm.end() || pp == byForm.end()) continue;
    const double ms = mean(s->second), mp = mean(pp->second);
    const std::string closer = ms < mp ? "summed" : "per_phase";
    ++wins[closer];
    summedAll += ms;
    perPhaseAll += mp;
    ++all;
    findings.rows.push_back({labels[key], std::to_string(s->second.size()), factor(ms), factor(mp), closer});
  }
  json summary = {{"boxes", boxes.size()}, {"model", kt::toString(model)}};
  if (all > 0) {
    const double ms = summedAll / static_cast<double>(all), mp = perPhaseAll / static_cast<double>(all);
    summary["mean_abs_log_deviation_summed"] = ms;
    summary["mean_abs_log_deviation_per_phase"] = mp;
    findings.headline =
        std::string(ms < mp ? "The summed form (MFiX's SUM_EpsGo)" : "The per-phase form (as printed)") +
        " is closer to DEM over " + std::to_string(boxes.size()) + " sheared boxes: off by a factor of " +
        core::humanNumber(std::exp(std::min(ms, mp)), 3) + " against " +
        core::humanNumber(std::exp(std::max(ms, mp)), 3) + " (geometric mean over " + std::to_string(all) +
        " quantities), closer in " + std::to_string(wins["summed"]) + " (summed) and " +
        std::to_string(wins["per_phase"]) + " (per phase) of them (" + std::string(kt::toString(model)) +
        ", Lebowitz g0, each phase's own energy balance" +
        (theory.rotation
             ? ", the rotation model's e_eff (beta0 " + core::humanNumber(theory.tangentialRestitution) + ")"
             : std::string()) +
        ").";
  }
  // The temperature ratio beside equipartition, which a reader needs to judge it: theta is per
  // unit mass, so equal energies per grain give theta_0 / theta_1 = m_1 / m_0.
  const auto range = [&](const std::function<double(const Box&)>& of) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Box& box : boxes) {
      const double v = of(box);
      if (!std::isfinite(v)) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    return std::isfinite(lo)
               ? (lo == hi ? core::humanNumber(lo, 3) : core::humanNumber(lo, 3) + "–" + core::humanNumber(hi, 3))
               : std::string("–");
  };
  const SpeciesPoint &s0 = boxes.front().species[0], &s1 = boxes.front().species[1];
  const double massRatio = s1.density * std::pow(s1.diameter, 3) / (s0.density * std::pow(s0.diameter, 3));
  findings.headline +=
      " θ_" + s0.name + " / θ_" + s1.name + ": DEM " + range([](const Box& b) { return b.temperatureRatio.value; });
  for (const Form& f : kForms) {
    findings.headline += ", " + std::string(f.name) + " " + range([&](const Box& b) {
                           const auto pred = predictAt(theory, f.form, b, b.mixtureFraction);
                           return pred[0].granularTemperature / pred[1].granularTemperature;
                         });
  }
  if (!ghdDeviations.empty()) {
    findings.headline +=
        ", Garzo-Hrenya-Dufty's zeroth order (energy exchanged between species) " +
        range([&](const Box& b) { return b.species.size() == 2 ? ghdThetaRatio(theory, b, b.mixtureFraction) : NAN; });
    summary["temperature_ratio_ghd_factor"] = std::exp(mean(ghdDeviations));
    findings.rows.push_back(
        {"θ ratio by GHD's zeroth order", std::to_string(ghdDeviations.size()), "", "", factor(mean(ghdDeviations))});
  }
  findings.headline += "; equal energy per grain would give m_" + s1.name + " / m_" + s0.name + " = " +
                       core::humanNumber(massRatio, 3) + ".";
  summary["temperature_ratio_equipartition"] = massRatio;

  // A figure per quantity against the total solid fraction: DEM per (composition, e) with
  // block-averaging errors, each form's steady shear at that composition as a line.
  const std::vector<Quantity> kinds = quantitiesOf(boxes.front());
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    report::Figure fig;
    fig.title = kinds[k].label;
    fig.x = {"total solid fraction φ", "–"};
    fig.y = {kinds[k].key == "temperature_ratio" ? "T ratio" : kinds[k].label, "–",
             kinds[k].key != "temperature_ratio"};
    std::map<std::pair<double, double>, std::pair<report::Series, const Box*>> dem;
    for (const Box& box : boxes) {
      const auto qs = quantitiesOf(box);
      if (k >= qs.size() || !std::isfinite(qs[k].dem.value)) continue;
      const double share = std::round(box.species[0].share * 100.0) / 100.0;
      auto& [s, ref] = dem[{share, box.species[0].restitution}];
      s.label = "DEM, x_" + box.species[0].name + " " + core::humanNumber(share) + ", e " +
                core::humanNumber(box.species[0].restitution);
      s.model = "DEM";
      s.style = report::Series::Style::PointsWithErrors;
      s.x.push_back(box.mixtureFraction);
      s.y.push_back(qs[k].dem.value / qs[k].unit);
      s.yError.push_back(qs[k].dem.error / qs[k].unit);
      ref = &box;
    }
    int variant = 0;
    for (auto& [state, entry] : dem) {
      auto& [s, ref] = entry;
      s.variant = variant;
      for (const Form& f : kForms) {
        report::Series curve;
        curve.label = std::string(f.name) + ", " + s.label.substr(5);
        curve.model = f.name;
        curve.colour = f.colour;
        curve.style = report::Series::Style::Line;
        curve.variant = variant;
        const Quantity q = quantitiesOf(*ref)[k];  // a copy: the vector is a temporary
        for (double phi = 0.02; phi <= 0.6001; phi += 0.01) {
          const double v = q.predicted(predictAt(theory, f.form, *ref, phi), q.species) / q.unit;
          if (std::isfinite(v) && (v > 0.0 || kinds[k].key == "temperature_ratio")) {
            curve.x.push_back(phi);
            curve.y.push_back(v);
          }
        }
        if (!curve.x.empty()) fig.series.push_back(std::move(curve));
      }
      if (kinds[k].key == "temperature_ratio" && ref->species.size() == 2) {
        report::Series curve;
        curve.label = "GHD zeroth order, " + s.label.substr(5);
        curve.model = "ghd";
        curve.colour = kGhdColour;
        curve.style = report::Series::Style::Line;
        curve.variant = variant;
        for (double phi = 0.02; phi <= 0.6001; phi += 0.01) {
          curve.x.push_back(phi);
          curve.y.push_back(ghdThetaRatio(theory, *ref, phi));
        }
        fig.series.push_back(std::move(curve));
      }
      fig.series.push_back(std::move(s));
      ++variant;
    }
    if (dem.empty()) continue;
    const auto drawn = report::drawFigure(fig, ctx.outputDir(), "compare_mixture_" + kinds[k].key);
    ctx.addArtifact(drawn.svg, "svg");
    ctx.addArtifact(drawn.png, "png");
    findings.figures.push_back({drawn.svg, drawn.png, fig.title});
  }
  ctx.setFindings(findings);
  ctx.setSummary(summary);
}

}  // namespace grainbridge::workflows::stages
