#include "workflows/stages/TabulateStage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "core/ClosureTable.hpp"
#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/Log.hpp"
#include "workflows/stages/TabulateRheology.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;
using params::ParamSpec;

TabulateStage::TabulateStage() {
  schema_
      .add(ParamSpec::string("table").required().doc("name of the closure tables (db query, engines load it by name)"))
      .add(ParamSpec::string("second_variable")
               .defaultValue("restitution")
               .options({"", "restitution", "volume_share"})
               .doc("second axis of the tables; \"\" for tables in solid fraction only; volume_share (the "
                    "species' share x of the solids volume) with `species`"))
      .add(ParamSpec::string("third_variable")
               .options({"restitution"})
               .doc("a third axis (issue 60): restitution, for a species' table over (total solid fraction, "
                    "volume_share, restitution); the points of every restitution then enter, without the "
                    "`restitution` filter (absent: no third axis)"))
      .add(ParamSpec::string("species").defaultValue("").doc(
          "a mixture's species (its name in the frames): tables of that species' closure points "
          "against the mixture's total solid fraction (issue 60); \"\" for the mixture's or one "
          "species' own points"))
      .add(ParamSpec::number("restitution")
               .min(0.0)
               .doc("use the points of this restitution only (a species table over volume_share is of one e)"))
      .add(ParamSpec::number("friction")
               .min(0.0)
               .doc("use the points of this friction coefficient (required when the points have several)"))
      .add(ParamSpec::number("fit_inertial_number_max")
               .defaultValue(0.5)
               .positive()
               .doc("the mu(I) and phi(I) fits take the points with inertial number up to this; above it "
                    "dilute, kinetic-theory flow follows other laws (phi(I) is linear only in dense flow)"))
      .add(ParamSpec::boolean("keep_ordered")
               .defaultValue(false)
               .doc("also table and fit the points whose box crystallised (closure_points.ordered: more than "
                    "20 % of the grains crystalline by the bond-orientational order); left out by default, as "
                    "their stresses are not those of the random packing a closure table means"));
}

namespace {

// States within this relative distance are the same grid node (measured solid fractions of one
// nominal state differ in the last digits only: a periodic box's volume is fixed).
// A mixture's boxes of one nominal state hold integer grain counts, so their total fractions
// differ by a few 1e-6 between compositions (the Goldschmidt pair's 0.2 is 0.1999993 at x 0.5 and
// 0.2000005 at x 0.75): a species' table takes nodes within 1e-4 as one.
constexpr double kNodeTolerance = 1e-6, kMixtureNodeTolerance = 1e-4;

bool same(double a, double b, double tolerance = kNodeTolerance) {
  return std::abs(a - b) <= tolerance * std::max({1.0, std::abs(a), std::abs(b)});
}

std::vector<double> distinct(std::vector<double> v, double tolerance = kNodeTolerance) {
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (double x : v) {
    if (out.empty() || !same(out.back(), x, tolerance)) out.push_back(x);
  }
  return out;
}

std::size_t indexOf(const std::vector<double>& axis, double x, double tolerance = kNodeTolerance) {
  for (std::size_t i = 0; i < axis.size(); ++i) {
    if (same(axis[i], x, tolerance)) return i;
  }
  return axis.size();
}

}  // namespace

void TabulateStage::checkParams(const json& p, const std::string& ptr, core::json::Diagnostics& d) const {
  if (p.at("second_variable") == "volume_share" && p.at("species").get<std::string>().empty()) {
    d.add(ptr + "/second_variable", "volume_share is a species' share of a mixture: give `species` too");
  }
  const std::string third = p.value("third_variable", std::string());
  if (!third.empty()) {
    if (p.at("second_variable") == "" || p.at("second_variable") == third) {
      d.add(ptr + "/third_variable", "a third axis needs a second one of another variable (second_variable is \"" +
                                         p.at("second_variable").get<std::string>() + "\")");
    }
    if (p.contains(third)) {
      d.add(ptr + "/" + third, "the table's third axis is " + third + ": its points are of every " + third +
                                   ", not filtered by one");
    }
  }
}

void TabulateStage::checkAgainstUpstream(const json& /*p*/, const std::string& ptr,
                                         const std::vector<UpstreamPlan>& upstream, core::json::Diagnostics& d) const {
  if (const auto* up = withoutClosurePoint(upstream)) {
    d.add(ptr, "upstream stage " + up->stage + " records no closure point: tabulate takes stages that do (extract)");
  }
}

void TabulateStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  const std::string name = p.at("table");
  const std::string second = p.at("second_variable");
  const std::string third = p.value("third_variable", std::string());
  const std::string species = p.at("species");
  std::vector<json> points;
  for (const auto& up : ctx.inputs()) {
    const auto records = up.records("closure_points");
    if (records.empty()) {
      throw Error("tabulate: upstream " + up.stage() + " (" + up.shortKey() +
                  ") recorded no closure point; tabulate takes stages that do (extract)");
    }
    json s = up.summary();
    if (!species.empty()) {
      // The species' row of a mixture's box, placed at the mixture's total solid fraction.
      const auto row = std::find_if(records.begin(), records.end(),
                                    [&](const json& r) { return r.value("species", std::string()) == species; });
      if (row == records.end()) {
        throw Error("/stages/" + ctx.stage() + "/params/species: upstream " + up.stage() + " (" + up.shortKey() +
                    ") recorded no closure point of species \"" + species +
                    "\" (a mixture's box periodic along every axis records one per species)");
      }
      s = *row;
      s["solid_fraction"] = row->at("mixture_solid_fraction");
    }
    s["__key"] = up.key();
    points.push_back(std::move(s));
  }
  if (points.empty()) throw Error("tabulate: no upstream extract instances; give it \"from\"");
  // Points whose box ordered (issue 61) stay in the database and out of the tables and fits.
  json excluded = json::array();
  if (!p.at("keep_ordered").get<bool>()) {
    std::erase_if(points, [&](const json& pt) {
      if (pt.value("ordered", 0) == 0) return false;
      spdlog::warn(
          "{}: leaving out the closure point of {} at solid fraction {:.4f}: its box ordered ({:.0f} % of "
          "the grains crystalline; keep_ordered keeps it)",
          ctx.stage(), pt["__key"].get<std::string>().substr(0, 12), pt.value("solid_fraction", 0.0),
          100.0 * pt.value("crystalline_share", 0.0));
      excluded.push_back(pt["__key"].get<std::string>().substr(0, 12));
      return true;
    });
    if (points.empty()) {
      throw Error("/stages/" + ctx.stage() +
                  "/params/keep_ordered: every closure point's box ordered; "
                  "keep_ordered: true tables them anyway");
    }
  }
  if (p.contains("restitution")) {
    const double e = p.at("restitution");
    std::erase_if(points, [&](const json& pt) { return !(pt.contains("restitution") && same(pt["restitution"], e)); });
    if (points.empty()) {
      throw Error("/stages/" + ctx.stage() + "/params/restitution: no closure point has restitution " +
                  std::to_string(e));
    }
  }

  // One friction per table.
  std::vector<double> frictions;
  for (const auto& pt : points) frictions.push_back(pt.value("friction", 0.0));
  frictions = distinct(frictions);
  double friction = frictions.front();
  if (p.contains("friction")) {
    friction = p.at("friction");
  } else if (frictions.size() > 1) {
    std::ostringstream msg;
    msg << "/stages/" << ctx.stage() << "/params/friction: the points have " << frictions.size()
        << " friction coefficients (";
    for (std::size_t i = 0; i < frictions.size(); ++i) msg << (i ? ", " : "") << frictions[i];
    msg << "); say which one this table is for";
    throw Error(msg.str());
  }
  std::erase_if(points, [&](const json& pt) { return !same(pt.value("friction", 0.0), friction); });
  if (points.empty()) {
    throw Error("/stages/" + ctx.stage() + "/params/friction: no closure point has friction " +
                std::to_string(friction));
  }

  std::vector<double> xs, ys, zs;
  for (const auto& pt : points) {
    xs.push_back(pt.at("solid_fraction"));
    for (const auto& [variable, values] : {std::pair{&second, &ys}, std::pair{&third, &zs}}) {
      if (variable->empty()) continue;
      if (!pt.contains(*variable))
        throw Error("tabulate: a closure point (" + pt["__key"].get<std::string>().substr(0, 12) + ") has no " +
                    *variable);
      values->push_back(pt.at(*variable));
    }
  }
  const double tolerance = species.empty() ? kNodeTolerance : kMixtureNodeTolerance;
  const auto xAxis = distinct(xs, tolerance);
  const auto yAxis = second.empty() ? std::vector<double>{} : distinct(ys, tolerance);
  const auto zAxis = third.empty() ? std::vector<double>{} : distinct(zs, tolerance);
  const std::size_t ny = std::max<std::size_t>(1, yAxis.size());
  const std::size_t rows = ny * std::max<std::size_t>(1, zAxis.size());
  std::vector<const json*> node(xAxis.size() * rows, nullptr);
  // The state of node k, for messages: values[(iz * ny + iy) * nx + ix].
  const auto state = [&](std::size_t k) {
    std::ostringstream out;
    out << "solid fraction " << xAxis[k % xAxis.size()];
    if (!second.empty()) out << ", " << second << " " << yAxis[(k / xAxis.size()) % ny];
    if (!third.empty()) out << ", " << third << " " << zAxis[k / (xAxis.size() * ny)];
    return out.str();
  };
  for (const auto& pt : points) {
    const std::size_t ix = indexOf(xAxis, pt.at("solid_fraction"), tolerance);
    const std::size_t iy = second.empty() ? 0 : indexOf(yAxis, pt.at(second), tolerance);
    const std::size_t iz = third.empty() ? 0 : indexOf(zAxis, pt.at(third), tolerance);
    const std::size_t k = (iz * ny + iy) * xAxis.size() + ix;
    auto& slot = node[k];
    if (slot != nullptr) {
      std::ostringstream msg;
      msg << "tabulate: two closure points at " << state(k);
      msg << " (from extract instances " << (*slot)["__key"].get<std::string>().substr(0, 12) << " and "
          << pt["__key"].get<std::string>().substr(0, 12) << ")";
      throw Error(msg.str());
    }
    slot = &pt;
  }
  for (std::size_t k = 0; k < node.size(); ++k) {
    if (node[k] == nullptr) {
      std::ostringstream msg;
      msg << "tabulate: no closure point at " << state(k) << ": the table needs every combination of the "
          << xAxis.size() << " solid fractions"
          << (second.empty() ? "" : (third.empty() ? " and " : ", ") + std::to_string(yAxis.size()) + " " + second + "s")
          << (third.empty() ? "" : " and " + std::to_string(zAxis.size()) + " " + third + "s");
      throw Error(msg.str());
    }
  }

  std::ostringstream csv;
  csv.precision(std::numeric_limits<double>::max_digits10);  // full precision: a CSV is read back by programs
  csv << "table,quantity,solid_fraction," << (second.empty() ? "second" : second) << (third.empty() ? "" : "," + third)
      << ",value,uncertainty\n";
  json summary = {{"table", name},
                  {"friction", friction},
                  {"solid_fractions", xAxis.size()},
                  {"rows", ny},
                  {"ordered_points_left_out", excluded.size()}};
  if (!third.empty()) summary[third + "_values"] = zAxis.size();
  json filters = {{"friction", friction}};
  if (!species.empty()) filters["species"] = species;
  if (p.contains("restitution")) filters["restitution"] = p.at("restitution");
  json quantities = json::array();
  const std::vector<std::string> forms{"p_theta", "eta_theta", "j_theta"};
  const auto everywhere = [&](const std::string& q) {
    return std::all_of(node.begin(), node.end(),
                       [&](const json* pt) { return pt->contains(q) && (*pt)[q].is_number(); });
  };
  for (const auto& q : forms) {
    if (!everywhere(q)) {
      spdlog::info("{}: no {} table: not every point has it (eta_theta needs sheared points)", ctx.stage(), q);
      continue;
    }
    std::vector<double> values, errors;
    for (const auto* pt : node) {
      values.push_back((*pt)[q]);
      errors.push_back(pt->value(q + "_err", 0.0));
    }
    // Per other form of the same points, the two's correlation at each node (extract's
    // <a>_<b>_corr, issue 63), for the joint closure draw; a point without it (made before it)
    // counts as uncorrelated.
    json correlations = json::object();
    for (const auto& other : forms) {
      if (other == q || !everywhere(other)) continue;
      const bool first = std::find(forms.begin(), forms.end(), q) < std::find(forms.begin(), forms.end(), other);
      const std::string column = first ? q + "_" + other + "_corr" : other + "_" + q + "_corr";
      std::vector<double> r;
      bool any = false;
      for (const auto* pt : node) {
        r.push_back(pt->value(column, 0.0));
        any = any || pt->contains(column);
      }
      if (any) correlations[other] = r;
    }
    // Building the table checks it (axes, finite values) before it reaches the database.
    core::ClosureTable table(q, xAxis, second, yAxis, third, zAxis, values);
    json record = {{"name", name},
                   {"quantity", q},
                   {"second_variable", second},
                   {"solid_fractions", xAxis},
                   {"seconds", yAxis},
                   {"values", values},
                   {"uncertainties", errors},
                   {"correlations", correlations},
                   {"filters", filters}};
    if (!third.empty()) {
      record["third_variable"] = third;
      record["thirds"] = zAxis;
    }
    ctx.addRecord("closure_tables", record);
    for (std::size_t k = 0; k < node.size(); ++k) {
      csv << name << ',' << q << ',' << xAxis[k % xAxis.size()] << ','
          << (second.empty() ? 0.0 : yAxis[(k / xAxis.size()) % ny]);
      if (!third.empty()) csv << ',' << zAxis[k / (xAxis.size() * ny)];
      csv << ',' << values[k] << ',' << errors[k] << '\n';
    }
    quantities.push_back(q);
  }
  if (quantities.empty()) throw Error("tabulate: the closure points have none of p_theta, eta_theta, j_theta");
  summary["quantities"] = quantities;
  core::writeFileAtomically(ctx.outputDir() / "tables.csv", csv.str());
  ctx.addArtifact("tables.csv", "csv");

  // The dense-flow rheology of the sheared points: mu(I), phi(I) and their fits.
  const auto rheology = tabulateRheology(points, name, p.at("fit_inertial_number_max").get<double>());
  if (!rheology.rows.empty()) {
    for (const auto& row : rheology.rows) ctx.addRecord("rheology", row);
    core::writeFileAtomically(ctx.outputDir() / "rheology_points.csv", rheology.pointsCsv);
    ctx.addArtifact("rheology_points.csv", "csv");
    core::writeFileAtomically(ctx.outputDir() / "rheology_fits.csv", rheology.fitsCsv);
    ctx.addArtifact("rheology_fits.csv", "csv");
    // Summary values are scalars (a report shows them as columns). Every row is in the CSVs and
    // the database; with one restitution its fits are summary values too, or why there is none.
    summary["rheology_rows"] = rheology.rows.size();
    const bool oneRestitution = std::all_of(rheology.summary.begin(), rheology.summary.end(), [&](const json& f) {
      return f.at("restitution") == rheology.summary.front().at("restitution");
    });
    if (oneRestitution) {
      for (const auto& fit : rheology.summary) {
        const std::string relation = fit.at("relation");
        for (const auto& [k, v] : fit.items()) {
          if (k == "fit" || k == "chi2_per_dof" || k == "fitted_points") {
            summary[relation + "_" + k] = v;
          } else if (k != "relation" && k != "restitution" && k != "points") {
            summary[k] = v;
          }
        }
      }
      // Which form describes the points better, by chi2/dof (issue 61).
      for (const std::string relation : {"mu_of_I", "phi_of_I"}) {
        const auto base = summary.find(relation + "_chi2_per_dof");
        const auto power = summary.find(relation + "_power_chi2_per_dof");
        if (base == summary.end() || power == summary.end()) continue;
        summary[relation + "_better_form"] =
            power->get<double>() < base->get<double>() ? "power_law" : (relation == "mu_of_I" ? "jop" : "linear");
      }
    }
  }
  ctx.setSummary(summary);
}

}  // namespace grainbridge::workflows::stages
