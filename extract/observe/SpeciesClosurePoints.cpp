#include "extract/observe/SpeciesClosurePoints.hpp"

#include <cmath>
#include <limits>

#include "core/ClosureForms.hpp"
#include "core/Error.hpp"
#include "core/averaging/BlockAverage.hpp"
#include "core/averaging/RatioOfMeans.hpp"
#include "extract/coarse/SpeciesStress.hpp"
#include "extract/coarse/StressMeasures.hpp"
#include "extract/observe/ThetaFormErrors.hpp"

namespace grainbridge::extract::observe {

using nlohmann::json;

namespace {

core::MeasuredValue averaged(const std::vector<double>& samples) {
  const auto b = core::averaging::blockAverage(samples);
  return {b.mean, b.standardError};
}

// -sigma_xy: positive where the shear does work on the grains (as the mixture's point).
double shearOf(const Mat3& stress) { return -stress(0, 1); }

}  // namespace

SpeciesClosurePoints::SpeciesClosurePoints(ClosurePointOptions options) : options_(std::move(options)) {
  perFrame_.precision(std::numeric_limits<double>::max_digits10);
}

void SpeciesClosurePoints::observe(ObservedFrame& observed) {
  const auto& frame = observed.frame;
  const auto parts = coarse::speciesStresses(frame, observed.domain.volume);
  if (frames_ == 0) {
    for (const auto& s : parts.species) species_.push_back(s.species);
    perSpecies_.resize(species_.size());
    perPair_.resize(parts.pairs.size());
    // Each species' diameter and density: the materials the frames carry, else the first
    // frame's grains (mean diameter, mass over volume).
    std::vector<double> sumD(species_.size(), 0.0), sumM(species_.size(), 0.0), sumV(species_.size(), 0.0);
    std::vector<std::size_t> count(species_.size(), 0);
    for (std::size_t i = 0; i < frame.size(); ++i) {
      const auto s = static_cast<std::size_t>(std::lower_bound(species_.begin(), species_.end(), frame.species[i]) -
                                              species_.begin());
      sumD[s] += 2.0 * frame.radius[i];
      sumM[s] += frame.mass[i];
      sumV[s] += 4.0 / 3.0 * M_PI * std::pow(frame.radius[i], 3);
      ++count[s];
    }
    for (std::size_t s = 0; s < species_.size(); ++s) {
      const auto id = static_cast<std::size_t>(species_[s]);
      const bool known = id < options_.materials.species.size();
      diameter_.push_back(known ? options_.materials.species[id].diameter : sumD[s] / static_cast<double>(count[s]));
      density_.push_back(known ? options_.materials.species[id].density : sumM[s] / sumV[s]);
    }
    perFrame_ << "time,step,mixture_solid_fraction";
    for (std::int32_t id : species_) {
      perFrame_ << ",solid_fraction_" << id << ",granular_temperature_" << id << ",pressure_" << id
                << ",pressure_kinetic_" << id << ",pressure_contact_" << id << ",shear_stress_" << id;
    }
    for (const auto& p : parts.pairs) {
      perFrame_ << ",pair_pressure_" << p.first << '_' << p.second << ",pair_shear_stress_" << p.first << '_'
                << p.second << ",pair_dissipation_rate_" << p.first << '_' << p.second;
    }
    perFrame_ << '\n';
  }
  if (parts.species.size() != species_.size()) {
    throw Error("species closure points: frame at t = " + std::to_string(frame.time) + " holds " +
                std::to_string(parts.species.size()) + " species, the first frame " + std::to_string(species_.size()));
  }
  ++frames_;
  mixtureFraction_.push_back(observed.domain.solidFraction);
  perFrame_ << frame.time << ',' << frame.step << ',' << observed.domain.solidFraction;
  for (std::size_t s = 0; s < species_.size(); ++s) {
    const auto& part = parts.species[s];
    if (part.species != species_[s]) {
      throw Error("species closure points: frame at t = " + std::to_string(frame.time) + " holds species " +
                  std::to_string(part.species) + " where the first frame held " + std::to_string(species_[s]));
    }
    Series& series = perSpecies_[s];
    series.solidFraction.push_back(part.solidFraction);
    series.temperature.push_back(part.granularTemperature);
    series.pressure.push_back(coarse::pressure(part.total()));
    series.pressureKinetic.push_back(coarse::pressure(part.kinetic));
    series.pressureContact.push_back(coarse::pressure(part.contact));
    series.shearStress.push_back(shearOf(part.total()));
    perFrame_ << ',' << part.solidFraction << ',' << part.granularTemperature << ',' << series.pressure.back() << ','
              << series.pressureKinetic.back() << ',' << series.pressureContact.back() << ','
              << series.shearStress.back();
  }
  for (std::size_t k = 0; k < parts.pairs.size(); ++k) {
    const auto& pair = parts.pairs[k];
    PairSeries& series = perPair_[k];
    series.pressure.push_back(coarse::pressure(pair.stress));
    series.shearStress.push_back(shearOf(pair.stress));
    series.dissipation.push_back(pair.dissipation);
    series.contacts.push_back(static_cast<double>(pair.contacts));
    perFrame_ << ',' << series.pressure.back() << ',' << series.shearStress.back() << ',' << series.dissipation.back();
  }
  perFrame_ << '\n';
}

void SpeciesClosurePoints::finish(OutputSink& out, ExtractResult& /*result*/) {
  if (species_.size() < 2) return;
  const core::MeasuredValue mixture = averaged(mixtureFraction_);
  const double shearRate = std::abs(options_.shearRate);
  const auto nameOf = [&](std::int32_t id) {
    const auto k = static_cast<std::size_t>(id);
    return k < options_.materials.species.size() && !options_.materials.species[k].name.empty()
               ? options_.materials.species[k].name
               : "species " + std::to_string(id);
  };
  const json provenance = {{"start_time", options_.startTime}, {"upstream_stage", options_.upstreamStage}};
  json rows = json::array();

  for (std::size_t s = 0; s < species_.size(); ++s) {
    const Series& series = perSpecies_[s];
    // Temperature and pressure block-averaged once: their means, errors and plateau verdicts.
    const auto blockedT = core::averaging::blockAverage(series.temperature);
    const auto blockedP = core::averaging::blockAverage(series.pressure);
    const core::MeasuredValue T{blockedT.mean, blockedT.standardError}, P{blockedP.mean, blockedP.standardError};
    const core::MeasuredValue eps = averaged(series.solidFraction), kinetic = averaged(series.pressureKinetic),
                              contact = averaged(series.pressureContact), tau = averaged(series.shearStress);
    json row = {{"family", options_.family},
                {"species", nameOf(species_[s])},
                {"solid_fraction", eps.mean},
                {"mixture_solid_fraction", mixture.mean},
                {"volume_share", mixture.mean > 0.0 ? eps.mean / mixture.mean : 0.0},
                {"diameter", diameter_[s]},
                {"density", density_[s]},
                {"frames", frames_},
                {"granular_temperature", T.mean},
                {"granular_temperature_err", T.error},
                {"pressure", P.mean},
                {"pressure_err", P.error}};
    json extra = provenance;
    extra["stress_partition"] = "contact point (Tunuguntla, Thornton and Weinhart 2016)";
    extra["temperature_about"] = "the mixture's mean velocity";
    extra["pressure_kinetic"] = kinetic.mean;
    extra["pressure_kinetic_err"] = kinetic.error;
    extra["pressure_contact"] = contact.mean;
    extra["pressure_contact_err"] = contact.error;
    extra["solid_fraction_err"] = eps.error;
    row["extra_json"] = extra;
    if (const auto own = options_.materials.pair(species_[s], species_[s])) {
      row["restitution"] = own->restitution;
      row["friction"] = own->friction;
    }
    const core::ClosureFormState state{density_[s], diameter_[s], T.mean, shearRate};
    addStressForms(row, P, tau, T, state);
    if (shearRate > 0.0) {
      // The species' J: the shear work on its partial stress, which in steady shear is its net
      // collisional loss (what its collisions dissipate, and what they hand the other species),
      // as the mixture's J is the whole shear work; the species' J add up to the mixture's.
      const core::MeasuredValue J{tau.mean * shearRate, tau.error * shearRate};
      row["dissipation_rate"] = J.mean;
      row["dissipation_rate_err"] = J.error;
      if (T.mean > 0.0) row["j_theta"] = core::toClosureForm(core::ClosureForm::JTheta, J.mean, state);
    }
    std::vector<std::string> noPlateau;
    if (!blockedT.plateauReached) noPlateau.emplace_back("granular_temperature");
    if (!blockedP.plateauReached) noPlateau.emplace_back("pressure");
    if (T.mean > 0.0) {
      // The forms' errors from the frame series, with their correlations (ThetaFormErrors.hpp).
      const auto forms = addThetaFormErrors(row, state, series.temperature, series.pressure, series.shearStress, {});
      noPlateau.insert(noPlateau.end(), forms.begin(), forms.end());
    }
    if (const auto warning = errorWarning(frames_, noPlateau)) row["error_warning"] = *warning;
    rows.push_back(std::move(row));
  }

  std::size_t k = 0;
  for (std::size_t a = 0; a < species_.size(); ++a) {
    for (std::size_t b = a; b < species_.size(); ++b, ++k) {
      const PairSeries& series = perPair_[k];
      const core::MeasuredValue P = averaged(series.pressure), tau = averaged(series.shearStress),
                                J = averaged(series.dissipation), contacts = averaged(series.contacts);
      const std::int32_t first = species_[a], second = species_[b];
      // The pair's own scale: its mean diameter and the mass-weighted density of the two species.
      const double sa = perSpecies_[a].solidFraction.front(), sb = perSpecies_[b].solidFraction.front();
      const double density = a == b ? density_[a] : (sa * density_[a] + sb * density_[b]) / (sa + sb);
      json row = {{"family", options_.family},
                  {"species", nameOf(first) + "+" + nameOf(second)},
                  {"solid_fraction", mixture.mean},
                  {"mixture_solid_fraction", mixture.mean},
                  {"diameter", 0.5 * (diameter_[a] + diameter_[b])},
                  {"density", density},
                  {"frames", frames_},
                  {"pressure", P.mean},
                  {"pressure_err", P.error},
                  {"dissipation_rate", J.mean},
                  {"dissipation_rate_err", J.error}};
      json extra = provenance;
      extra["contribution"] = "the pair's contacts only (r_ij F over them, Eq. 2.3; their dashpots' power)";
      extra["contacts"] = contacts.mean;
      extra["contacts_err"] = contacts.error;
      extra["solid_fraction_err"] = mixture.error;
      if (a != b) {
        const auto ratio = core::averaging::ratioOfMeans(perSpecies_[a].temperature, perSpecies_[b].temperature);
        extra["temperature_ratio"] = ratio.value;  // T_first / T_second
        extra["temperature_ratio_err"] = ratio.standardError;
      }
      row["extra_json"] = extra;
      if (const auto pair = options_.materials.pair(first, second)) {
        row["restitution"] = pair->restitution;
        row["friction"] = pair->friction;
      }
      if (shearRate > 0.0) {
        row["shear_rate"] = shearRate;
        row["shear_stress"] = tau.mean;
        row["shear_stress_err"] = tau.error;
      }
      rows.push_back(std::move(row));
    }
  }

  std::ostringstream csv;
  csv.precision(std::numeric_limits<double>::max_digits10);
  csv << "species,solid_fraction,mixture_solid_fraction,volume_share,diameter,density,granular_temperature,"
         "granular_temperature_err,pressure,pressure_err,shear_stress,shear_stress_err,p_theta,p_theta_err,eta_theta,"
         "eta_theta_err,dissipation_rate,dissipation_rate_err\n";
  for (const json& row : rows) {
    csv << row.at("species").get<std::string>();
    for (const char* key :
         {"solid_fraction", "mixture_solid_fraction", "volume_share", "diameter", "density", "granular_temperature",
          "granular_temperature_err", "pressure", "pressure_err", "shear_stress", "shear_stress_err", "p_theta",
          "p_theta_err", "eta_theta", "eta_theta_err", "dissipation_rate", "dissipation_rate_err"}) {
      csv << ',';
      if (row.contains(key)) csv << row[key].get<double>();
    }
    csv << '\n';
  }
  out.writeFile("species_points.csv", csv.str(), "csv");
  out.writeFile("species_frames.csv", perFrame_.str(), "csv");
  for (json& row : rows) out.addRecord("closure_points", std::move(row));
}

}  // namespace grainbridge::extract::observe
