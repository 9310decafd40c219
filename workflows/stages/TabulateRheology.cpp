#include "workflows/stages/TabulateRheology.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/text/NumberText.hpp"
#include "core/SameValue.hpp"
#include "extract/statistics/InertialRheologyFit.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;
namespace st = extract::statistics;

namespace {


// The restitution a point belongs to; points without one (a particle gas) form one group.
std::optional<double> restitutionOf(const json& point) {
  if (!point.contains("restitution") || !point["restitution"].is_number()) return std::nullopt;
  return point["restitution"].get<double>();
}

struct Relation {
  st::RheologyRelation kind;
  const char* value;  // the point's column
  const char* error;  // its error's column
};

// Each relation in two forms: Jop et al.'s mu(I) and the linear phi(I), and the power laws near
// the critical point (issue 61); the summary says which fits better (chi2/dof).
constexpr Relation kRelations[] = {
    {st::RheologyRelation::MuOfI, "stress_ratio", "stress_ratio_err"},
    {st::RheologyRelation::PhiOfI, "solid_fraction", "solid_fraction_err"},
    {st::RheologyRelation::MuOfIPower, "stress_ratio", "stress_ratio_err"},
    {st::RheologyRelation::PhiOfIPower, "solid_fraction", "solid_fraction_err"},
};

// The fit, or why there is none.
struct FitOutcome {
  std::optional<st::RheologyFit> fit;
  std::string why;
};

FitOutcome fitOrExplain(st::RheologyRelation relation, const std::vector<st::RheologySample>& samples) {
  try {
    return {st::fitRheology(relation, samples), ""};
  } catch (const Error& e) {
    return {std::nullopt, e.what()};
  }
}

}  // namespace

TabulatedRheology tabulateRheology(const std::vector<json>& points, const std::string& name, double fitMax) {
  std::vector<const json*> sheared;
  for (const auto& pt : points) {
    if (pt.contains("inertial_number") && pt["inertial_number"].is_number() && pt.contains("stress_ratio")) {
      sheared.push_back(&pt);
    }
  }
  TabulatedRheology out;
  std::ostringstream pointsCsv, fitsCsv;
  pointsCsv.precision(std::numeric_limits<double>::max_digits10);
  fitsCsv.precision(std::numeric_limits<double>::max_digits10);
  pointsCsv << "table,relation,restitution,inertial_number,inertial_number_err,value,uncertainty,fitted\n";
  fitsCsv << "table,relation,restitution,parameter,value,error,chi2_per_dof,dof,fitted_points\n";
  if (sheared.empty()) return out;

  // A rheology is of one kind of grain: I is made with the grains' diameter and density.
  const double diameter = sheared.front()->at("diameter"), density = sheared.front()->at("density");
  for (const auto* pt : sheared) {
    if (!core::sameValue(pt->at("diameter"), diameter) || !core::sameValue(pt->at("density"), density)) {
      throw Error("tabulate: the closure points are of different grains (diameter " + core::humanNumber(diameter) +
                  " and " + core::humanNumber(pt->at("diameter").get<double>()) + " m, density " +
                  core::humanNumber(density) + " and " + core::humanNumber(pt->at("density").get<double>()) +
                  " kg/m3); a rheology table is of one kind of grain");
    }
  }

  // Groups by restitution, in increasing order (no restitution first).
  std::vector<std::pair<std::optional<double>, std::vector<const json*>>> groups;
  for (const auto* pt : sheared) {
    const auto e = restitutionOf(*pt);
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) {
      return g.first.has_value() == e.has_value() && (!e || core::sameValue(*g.first, *e));
    });
    if (it == groups.end()) {
      groups.push_back({e, {}});
      it = groups.end() - 1;
    }
    it->second.push_back(pt);
  }
  std::sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) { return a.first < b.first; });

  for (auto& [restitution, group] : groups) {
    std::sort(group.begin(), group.end(), [](const json* a, const json* b) {
      return a->at("inertial_number").get<double>() < b->at("inertial_number").get<double>();
    });
    const json e = restitution ? json(*restitution) : json();
    const std::string eText = restitution ? core::humanNumber(*restitution) : std::string();
    for (const auto& relation : kRelations) {
      std::vector<double> I, IErr, value, valueErr;
      std::vector<st::RheologySample> fitted;
      for (const auto* pt : group) {
        I.push_back(pt->at("inertial_number"));
        IErr.push_back(pt->value("inertial_number_err", 0.0));
        value.push_back(pt->at(relation.value));
        valueErr.push_back(pt->value(relation.error, 0.0));
        const bool inFit = I.back() <= fitMax;
        if (inFit) fitted.push_back({I.back(), IErr.back(), value.back(), valueErr.back()});
        // The points once per relation (its power-law form fits the same points).
        if (st::fitKey(relation.kind) != st::relationName(relation.kind)) continue;
        pointsCsv << name << ',' << st::relationName(relation.kind) << ',' << eText << ',' << I.back() << ','
                  << IErr.back() << ',' << value.back() << ',' << valueErr.back() << ',' << (inFit ? 1 : 0) << '\n';
      }
      json row = {{"name", name},
                  {"family", group.front()->value("family", std::string("unknown"))},
                  {"relation", st::relationName(relation.kind)},
                  {"form", st::formName(relation.kind)},
                  {"restitution", e},
                  {"friction", group.front()->contains("friction") ? group.front()->at("friction") : json()},
                  {"diameter", diameter},
                  {"density", density},
                  {"points", I.size()},
                  {"inertial_numbers_json", I},
                  {"inertial_number_errors_json", IErr},
                  {"values_json", value},
                  {"uncertainties_json", valueErr},
                  {"fit_inertial_number_max", fitMax},
                  {"fitted_points", fitted.size()}};
      json brief = {{"relation", st::fitKey(relation.kind)},
                    {"restitution", e},
                    {"points", I.size()},
                    {"fitted_points", fitted.size()}};
      const std::size_t needed = relation.kind == st::RheologyRelation::PhiOfI ? 3 : 4;
      if (fitted.size() < needed) {
        // Expected on a dilute sweep (the quickstart's), so not a line per relation and restitution
        // in every run's log: the summary says it, the log at -v.
        const std::string why = std::to_string(fitted.size()) + " points with I <= " + core::humanNumber(fitMax) +
                                ", too few to fit (needs " + std::to_string(needed) + ")";
        spdlog::debug("tabulate {}: {} at restitution {}: {}", name, st::fitKey(relation.kind),
                      eText.empty() ? "-" : eText, why);
        brief["fit"] = "none: " + why;
      } else if (const auto [fit, why] = fitOrExplain(relation.kind, fitted); !fit) {
        // Points that do not determine the law (mu not rising with I, I_0 outside the points'
        // range) are still a table; the fit's absence is said, not turned into a failed stage.
        spdlog::warn("tabulate {}: {} at restitution {}: {}", name, st::fitKey(relation.kind),
                     eText.empty() ? "-" : eText, why);
        brief["fit"] = "none: " + why;
      } else {
        json covariance = json::array();
        for (Eigen::Index r = 0; r < fit->covariance.rows(); ++r) {
          json line = json::array();
          for (Eigen::Index c = 0; c < fit->covariance.cols(); ++c) line.push_back(fit->covariance(r, c));
          covariance.push_back(std::move(line));
        }
        for (std::size_t k = 0; k < fit->names.size(); ++k) {
          const auto i = static_cast<Eigen::Index>(k);
          row[fit->names[k]] = fit->params[i];
          row[fit->names[k] + "_err"] = fit->errors[i];
          brief[fit->names[k]] = fit->params[i];
          brief[fit->names[k] + "_err"] = fit->errors[i];
          fitsCsv << name << ',' << st::fitKey(relation.kind) << ',' << eText << ',' << fit->names[k] << ','
                  << fit->params[i] << ',' << fit->errors[i] << ',' << fit->chi2PerDof << ',' << fit->dof << ','
                  << fit->points << '\n';
        }
        row["covariance_json"] = covariance;
        row["chi2_per_dof"] = fit->chi2PerDof;
        row["dof"] = fit->dof;
        row["weighted"] = fit->weighted ? 1 : 0;
        brief["chi2_per_dof"] = fit->chi2PerDof;
      }
      out.rows.push_back(std::move(row));
      out.summary.push_back(std::move(brief));
    }
  }
  out.pointsCsv = pointsCsv.str();
  out.fitsCsv = fitsCsv.str();
  return out;
}

}  // namespace grainbridge::workflows::stages
