#include "extract/observe/ClosurePointObserver.hpp"

#include <cmath>
#include <limits>

#include "core/ClosureForms.hpp"
#include "core/Log.hpp"
#include "core/averaging/BlockAverage.hpp"
#include "core/averaging/RatioOfMeans.hpp"
#include "core/text/NumberText.hpp"
#include "extract/coarse/DissipationRate.hpp"
#include "extract/observe/ThetaFormErrors.hpp"
#include "extract/structure/BondOrder.hpp"

namespace grainbridge::extract::observe {

using nlohmann::json;

namespace {

// One time-averaged quantity: mean, block-averaging standard error, and whether the blocking
// curve reached its plateau (if not, the error is a lower bound).
struct Averaged {
  double mean = 0.0;
  double error = 0.0;
  bool plateauReached = true;
};

Averaged averaged(const std::vector<double>& samples) {
  const auto b = core::averaging::blockAverage(samples);
  return {b.mean, b.standardError, b.plateauReached};
}

}  // namespace

ClosurePointObserver::ClosurePointObserver(ClosurePointOptions options) : options_(std::move(options)) {
  perFrame_.precision(std::numeric_limits<double>::max_digits10);  // full precision: read back by programs
  perFrame_ << "time,step,solid_fraction,granular_temperature,pressure,pressure_kinetic,pressure_contact,sigma_xy,"
               "dissipation_rate_dashpots,coordination,multi_contact_ratio,bond_order_q6,crystalline_share\n";
}

void ClosurePointObserver::observe(ObservedFrame& observed) {
  const auto& frame = observed.frame;
  const auto& a = observed.domain;
  const double J = coarse::dissipationRate(frame, a.volume);
  solidFraction_.push_back(a.solidFraction);
  temperature_.push_back(a.granularTemperature);
  pressure_.push_back(a.pressure);
  shearStress_.push_back(-a.stress(0, 1));  // positive where the shear does work on the grains
  dissipation_.push_back(J);
  coordination_.push_back(a.coordinationNumber);
  if (diameter_ == 0.0) {
    // Mean diameter and material density of the grains (monodisperse closures; a mixture's
    // points carry the number-mean diameter).
    double sumD = 0.0, sumM = 0.0, sumV = 0.0;
    for (std::size_t i = 0; i < frame.size(); ++i) {
      sumD += 2.0 * frame.radius[i];
      sumM += frame.mass[i];
      sumV += 4.0 / 3.0 * M_PI * std::pow(frame.radius[i], 3);
    }
    diameter_ = sumD / static_cast<double>(frame.size());
    density_ = sumM / sumV;
  }
  // How crystalline the frame is (structure/BondOrder): neighbours within 1.3 mean diameters.
  const auto order = structure::bondOrder(frame.domain, frame.position, kBondOrderCutoff * diameter_);
  bondOrderQ6_.push_back(order.meanQ6);
  crystallineShare_.push_back(order.crystallineShare);
  ++frames_;
  perFrame_ << frame.time << ',' << frame.step << ',' << a.solidFraction << ',' << a.granularTemperature << ','
            << a.pressure << ',' << a.kineticStress.trace() / 3.0 << ',' << a.contactStress.trace() / 3.0 << ','
            << a.stress(0, 1) << ',' << J << ',' << a.coordinationNumber << ',' << a.multiContactRatio << ','
            << order.meanQ6 << ',' << order.crystallineShare << '\n';
}

void ClosurePointObserver::finish(OutputSink& out, ExtractResult& result) {
  out.writeFile("frames.csv", perFrame_.str(), "csv");

  const Averaged eps = averaged(solidFraction_), T = averaged(temperature_), P = averaged(pressure_),
                 tau = averaged(shearStress_), Z = averaged(coordination_), dashpots = averaged(dissipation_);
  // The dissipation rate J. The frames' dashpot forces give the power the contacts' dashpots
  // take out of the relative motion (DissipationRate.hpp). With friction that misses the Coulomb
  // sliding loss (the tangential spring cut back to the cap) and the tangential spring energy a
  // contact carries off when it opens: at friction 0.5 in the shear sweep the dashpots took only
  // 9-56 % of the shear work. In steady Lees-Edwards shear the work done by the shear,
  // -sigma_xy gammadot, is the whole dissipation (energy balance, VALIDATION.md), with a smaller
  // error too, so it is J there; the dashpot figure stays in extra_json, and for frictionless
  // grains their ratio is the check that the averaged window is a steady state. Without shear
  // the dashpots are all there is: exact for frictionless grains, a lower bound with friction.
  const double shearRate = options_.shearRate;
  const bool fromShearWork = shearRate != 0.0;
  const Averaged J = fromShearWork
                         ? Averaged{tau.mean * std::abs(shearRate), tau.error * std::abs(shearRate), tau.plateauReached}
                         : dashpots;
  json row = {{"family", options_.family},
              {"solid_fraction", eps.mean},
              {"diameter", diameter_},
              {"density", density_},
              {"frames", frames_},
              {"granular_temperature", T.mean},
              {"granular_temperature_err", T.error},
              {"pressure", P.mean},
              {"pressure_err", P.error},
              {"dissipation_rate", J.mean},
              {"dissipation_rate_err", J.error},
              {"coordination", Z.mean},
              {"coordination_err", Z.error},
              {"extra_json",
               {{"solid_fraction_err", eps.error},
                {"start_time", options_.startTime},
                {"upstream_stage", options_.upstreamStage},
                {"dissipation_rate_source", fromShearWork ? "shear_work" : "contact_dashpots"},
                {"dissipation_rate_dashpots", dashpots.mean},
                {"dissipation_rate_dashpots_err", dashpots.error}}}};
  // How ordered the box was (issue 61): a point whose grains crystallised is flagged, kept, and
  // left out of tables unless asked for (tabulate's keep_ordered).
  const Averaged q6 = averaged(bondOrderQ6_), crystalline = averaged(crystallineShare_);
  row["bond_order_q6"] = q6.mean;
  row["bond_order_q6_err"] = q6.error;
  row["crystalline_share"] = crystalline.mean;
  row["crystalline_share_err"] = crystalline.error;
  row["ordered"] = crystalline.mean > kOrderedShare ? 1 : 0;
  if (crystalline.mean > kOrderedShare) {
    spdlog::warn(
        "{}: {:.0f} % of the grains are crystalline (bond-orientational order q6 {:.3f}): the box ordered, "
        "and the point is flagged ordered (tables leave it out unless keep_ordered)",
        out.label(), 100.0 * crystalline.mean, q6.mean);
  }
  // The state the point belongs to: restitution and friction of the first species pair, from
  // the materials the frames carry (frames without contact materials, a particle gas, have none).
  if (!options_.materials.pairs.empty()) {
    row["restitution"] = options_.materials.pairs.front().restitution;
    row["friction"] = options_.materials.pairs.front().friction;
  }
  if (fromShearWork && row.contains("friction") && row["friction"].get<double>() == 0.0 && J.mean > 0.0) {
    // Frictionless grains lose energy in the dashpots only: shear work above them is heating.
    const double gap = std::abs(dashpots.mean - J.mean);
    if (gap > 3.0 * std::hypot(dashpots.error, J.error) + 0.05 * J.mean) {
      spdlog::warn(
          "{}: the shear work ({} W/m3) and the dashpot dissipation ({} W/m3) of these frictionless grains "
          "differ by {:.0f} %: the averaged frames are not a steady state (raise start_strain or run longer)",
          out.label(), core::humanNumber(J.mean, 4), core::humanNumber(dashpots.mean, 4), 100.0 * gap / J.mean);
    }
  }
  // The closure forms (core/ClosureForms), each with its block-averaging error.
  const core::ClosureFormState state{density_, diameter_, T.mean, std::abs(shearRate)};
  addStressForms(row, {P.mean, P.error}, {tau.mean, tau.error}, {T.mean, T.error}, state);
  std::vector<std::string> noPlateau;
  for (const auto& [name, a] :
       {std::pair{"granular_temperature", T}, std::pair{"pressure", P}, std::pair{"dissipation_rate", J}}) {
    if (!a.plateauReached) noPlateau.emplace_back(name);
  }
  if (T.mean > 0.0) {
    row["j_theta"] = core::toClosureForm(core::ClosureForm::JTheta, J.mean, state);
    const auto forms = addThetaFormErrors(row, state, temperature_, pressure_, shearStress_, dissipation_);
    noPlateau.insert(noPlateau.end(), forms.begin(), forms.end());
  }
  if (const auto warning = errorWarning(frames_, noPlateau)) {
    row["error_warning"] = *warning;
    spdlog::warn("{}: {}", out.label(), *warning);
  }
  if (shearRate != 0.0 && P.mean > 0.0) {
    // The dense-flow variables (Chialvo, Sun and Sundaresan 2012, PRE 85 021305): the inertial
    // number I = gammadot d / sqrt(p / rho_p), whose relative error is half the pressure's,
    // and the stress ratio tau / p, its error from the frame series (RatioOfMeans.hpp).
    const double I = std::abs(shearRate) * diameter_ / std::sqrt(P.mean / density_);
    row["inertial_number"] = I;
    row["inertial_number_err"] = 0.5 * I * P.error / P.mean;
    const auto ratio = core::averaging::ratioOfMeans(shearStress_, pressure_);
    row["stress_ratio"] = ratio.value;
    row["stress_ratio_err"] = ratio.standardError;
  }
  result.point = std::move(row);
}

void addStressForms(json& row, const core::MeasuredValue& pressure, const core::MeasuredValue& shearStress,
                    const core::MeasuredValue& temperature, const core::ClosureFormState& state) {
  const auto addForm = [&](core::ClosureForm form, const core::MeasuredValue& value) {
    const std::string name(core::closureFormInfo(form).name);
    row[name] = core::toClosureForm(form, value.mean, state);
    row[name + "_err"] = core::closureFormError(form, value, temperature, state);
  };
  // The theta-scaled forms a continuum engine uses with its own temperature (DESIGN.md).
  if (temperature.mean > 0.0) addForm(core::ClosureForm::PTheta, pressure);
  const double g = state.shearRate;
  if (g == 0.0) return;
  row["shear_rate"] = g;
  row["shear_stress"] = shearStress.mean;
  row["shear_stress_err"] = shearStress.error;
  const core::MeasuredValue mu{shearStress.mean / g, shearStress.error / g};
  row["viscosity"] = mu.mean;
  row["viscosity_err"] = mu.error;
  addForm(core::ClosureForm::PShear, pressure);
  addForm(core::ClosureForm::TauShear, shearStress);
  addForm(core::ClosureForm::TShear, temperature);
  if (temperature.mean > 0.0) addForm(core::ClosureForm::EtaTheta, mu);
}

std::string closurePointCsv(const json& point) {
  std::ostringstream csv;
  csv.precision(std::numeric_limits<double>::max_digits10);
  csv << "quantity,value\n";
  for (const auto& [k, v] : point.items()) {
    if (v.is_number()) csv << k << ',' << v.get<double>() << '\n';
  }
  return csv.str();
}

}  // namespace grainbridge::extract::observe
