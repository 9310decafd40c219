#include "workflows/report/BedFindings.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/text/NumberText.hpp"
#include "workflows/report/CsvField.hpp"

namespace grainbridge::workflows::report {

namespace {

std::string percent(double relative) {
  return (relative >= 0 ? "+" : "−") + core::humanNumber(std::abs(100.0 * relative), 2) + " %";
}

std::string withError(double v, double err, int significant = 4) {
  if (!std::isfinite(v)) return "–";
  return core::humanNumber(v, significant) + (std::isfinite(err) && err > 0 ? " ± " + core::humanNumber(err, 2) : "");
}

std::string number(double v) { return std::isfinite(v) ? core::roundTripText(v) : std::string(); }

// "± 0.0011 (DEM closures, 8 joint samples scattering by 0.0013, less their own fluctuation
// errors), mostly from p_theta (72 %)" for an output of a run
// with closure samples; "" without.
std::string closurePart(const BedRun& run, const std::string& output, int significant) {
  const auto it = run.closureSpreads.find(output);
  if (it == run.closureSpreads.end()) return "";
  const ClosureSpread& c = it->second;
  std::string text = " ± " + core::humanNumber(c.spread, significant) + " (DEM closures, ";
  text += c.fromJoint ? std::to_string(c.jointSamples) + " joint samples" : "one-at-a-time samples";
  text += " scattering by " + core::humanNumber(c.scatter, significant) + ", less their own fluctuation errors)";
  if (const std::string top = c.dominant(); !top.empty()) {
    for (const auto& q : c.quantities) {
      if (q.quantity == top) text += ", mostly from " + top + " (" + core::humanNumber(100.0 * q.share, 2) + " %)";
    }
  }
  return text;
}

}  // namespace

std::string bedsCsv(const std::vector<BedRun>& runs, const std::vector<std::string>& referenceLabels) {
  std::ostringstream csv;
  csv << "run,closure,mean_height,mean_height_err,pressure_drop,pressure_drop_err,dp_frequency,dp_amplitude,"
         "table_coverage_cell_steps,table_coverage_solids,solver_steps,retries,segregation_percentage,"
         "segregation_percentage_err,mean_height_fields,mean_height_fields_err,bed_weight,coordination,"
         "coordination_err,multi_contact_ratio,multi_contact_ratio_err,closure_samples";
  // The spread from the DEM closures of each output and each table quantity's share of it.
  for (const auto& output : kClosureSampledOutputs) {
    csv << ',' << output << "_closure";
    for (const auto& q : kClosureSampledQuantities) csv << ',' << output << "_share_" << q;
  }
  csv << ",reference,reference_kind,reference_height,deviation\n";
  for (const auto& run : runs) {
    std::string fields = csvField(run.label) + ',' + run.closure + ',' + number(run.meanHeight) + ',' +
                         number(run.meanHeightError);
    for (const char* k : {"pressure_drop", "pressure_drop_err", "dp_frequency", "dp_amplitude",
                          "table_coverage_cell_steps", "table_coverage_solids", "solver_steps", "retries",
                          "segregation_percentage", "segregation_percentage_err", "mean_height_fields",
                          "mean_height_fields_err", "bed_weight", "coordination", "coordination_err",
                          "multi_contact_ratio", "multi_contact_ratio_err"}) {
      fields += ',' + number(run.value(k));
    }
    fields += ',' + (run.closureSamples > 0 ? std::to_string(run.closureSamples) : std::string());
    for (const auto& output : kClosureSampledOutputs) {
      const auto it = run.closureSpreads.find(output);
      fields += ',' + (it == run.closureSpreads.end() ? std::string() : number(it->second.spread));
      for (const auto& q : kClosureSampledQuantities) {
        double share = NAN;
        if (it != run.closureSpreads.end()) {
          for (const auto& s : it->second.quantities) share = s.quantity == q ? s.share : share;
        }
        fields += ',' + number(share);
      }
    }
    bool matchedAny = false;
    for (const auto& label : referenceLabels) {
      for (const auto& r : run.references) {
        if (r.label != label) continue;
        csv << fields << ',' << csvField(r.label) << ',' << r.kind << ',' << number(r.height) << ','
            << number((run.meanHeight - r.height) / r.height) << '\n';
        matchedAny = true;
      }
    }
    if (!matchedAny) csv << fields << ",,,,\n";
  }
  return csv.str();
}

Findings bedFindings(const std::vector<BedRun>& runs, const std::vector<std::string>& referenceLabels,
                     const std::string& title) {
  Findings findings;
  findings.title = title;
  findings.details = "bed_compare.html";
  const bool anyTable = std::any_of(runs.begin(), runs.end(), [](const BedRun& r) { return r.closure == "table"; });
  findings.columns = {"run", "closure", "mean height [m]"};
  for (const auto& l : referenceLabels) findings.columns.push_back("vs " + l);
  // Particle runs (tfdem) report the particles' arithmetic mean height; Eq. 5.22 of their deposited
  // fraction, what a multi-fluid run reports, stands beside it.
  const auto records = [&runs](const char* k) {
    return std::any_of(runs.begin(), runs.end(), [k](const BedRun& r) { return std::isfinite(r.value(k)); });
  };
  const bool anyDeposited = records("mean_height_fields");
  const bool anyContacts = records("coordination");
  const bool anyWeight = records("bed_weight");
  if (anyDeposited) findings.columns.emplace_back("Eq. 5.22 of deposited fields [m]");
  if (anyWeight) findings.columns.emplace_back("bed weight [Pa]");
  findings.columns.emplace_back("pressure drop [Pa]");
  findings.columns.emplace_back("Δp frequency [Hz]");
  findings.columns.emplace_back("Δp amplitude [Pa]");
  if (anyContacts) findings.columns.emplace_back("coordination / multi-contact ratio");
  if (anyTable) findings.columns.emplace_back("table coverage (cell-steps / solids)");
  const bool anyBinary = std::any_of(runs.begin(), runs.end(),
                                     [](const BedRun& r) { return std::isfinite(r.value("segregation_percentage")); });
  if (anyBinary) findings.columns.emplace_back("segregation percentage s_p [%]");
  const bool anySamples = std::any_of(runs.begin(), runs.end(), [](const BedRun& r) { return r.closureSamples > 0; });
  if (anySamples) findings.columns.emplace_back("height spread from the DEM closures [m]");
  std::ostringstream headline;
  // The headline leads with what the DEM closures' own error does to each sampled run's answer.
  for (const auto& run : runs) {
    if (run.closureSamples == 0) continue;
    headline << run.label << ": bed height " << core::humanNumber(run.meanHeight, 4) << " m ± "
             << core::humanNumber(run.meanHeightError, 2) << " (bed fluctuations)"
             << closurePart(run, "mean_height", 2);
    if (std::isfinite(run.value("pressure_drop"))) {
      headline << "; pressure drop " << core::humanNumber(run.value("pressure_drop"), 4) << " Pa ± "
               << core::humanNumber(run.value("pressure_drop_err"), 2) << closurePart(run, "pressure_drop", 2);
    }
    if (std::isfinite(run.value("segregation_percentage"))) {
      headline << "; segregation percentage " << core::humanNumber(run.value("segregation_percentage"), 3) << " ± "
               << core::humanNumber(run.value("segregation_percentage_err"), 2) << " %"
               << closurePart(run, "segregation_percentage", 2);
    }
    headline << " (" << run.closureSamples << " closure samples). ";
  }
  for (const auto& run : runs) {
    const double h = run.meanHeight, hErr = run.meanHeightError;
    const double frequency = run.value("dp_frequency");
    // The table names a run as the legends do (what differs between the runs): a table of long
    // sweep labels ran off a 1280 px page; beds.csv keeps the full label.
    std::vector<std::string> row = {run.shortLabel.empty() ? run.label : run.shortLabel, run.closure,
                                    withError(h, hErr)};
    std::ostringstream compared;
    for (const auto& l : referenceLabels) {
      std::string cell = "–";
      for (const auto& r : run.references) {
        if (r.label != l) continue;
        const double deviation = (h - r.height) / r.height;
        cell = core::humanNumber(r.height, 4) + " m: " + percent(deviation);
        compared << (compared.tellp() > 0 ? "; " : "") << r.label << " " << core::humanNumber(r.height, 4)
                 << " m: " << percent(deviation);
      }
      row.push_back(cell);
    }
    const double deposited = run.value("mean_height_fields");
    if (anyDeposited) row.push_back(withError(deposited, run.value("mean_height_fields_err")));
    if (anyWeight) row.push_back(withError(run.value("bed_weight"), NAN));
    row.push_back(withError(run.value("pressure_drop"), run.value("pressure_drop_err")));
    row.push_back(std::isfinite(frequency) ? core::humanNumber(frequency, 3) : "–");
    const double amplitude = run.value("dp_amplitude");
    row.push_back(std::isfinite(amplitude) ? core::humanNumber(amplitude, 3) : "–");
    const double coordination = run.value("coordination");
    if (anyContacts) {
      row.push_back(std::isfinite(coordination)
                        ? withError(coordination, run.value("coordination_err"), 3) + " / " +
                              withError(run.value("multi_contact_ratio"), run.value("multi_contact_ratio_err"), 3)
                        : "–");
    }
    std::string coverage;
    if (run.closure == "table") {
      coverage = core::humanNumber(100.0 * run.value("table_coverage_cell_steps"), 3) + " % / " +
                 core::humanNumber(100.0 * run.value("table_coverage_solids"), 3) + " %";
    }
    if (anyTable) row.push_back(run.closure == "table" ? coverage : "–");
    const double sp = run.value("segregation_percentage");
    if (anyBinary) row.push_back(withError(sp, run.value("segregation_percentage_err"), 3));
    if (anySamples) {
      const auto it = run.closureSpreads.find("mean_height");
      row.push_back(it == run.closureSpreads.end() ? "–" : closurePart(run, "mean_height", 2).substr(3));
    }
    findings.rows.push_back(std::move(row));
    headline << run.label << ": mean particle height " << withError(h, hErr) << " m";
    if (std::isfinite(deposited)) {
      headline << " over the particles (Eq. 5.22 of their deposited fraction "
               << withError(deposited, run.value("mean_height_fields_err")) << " m)";
    }
    if (compared.tellp() > 0) headline << " (" << compared.str() << ")";
    const double dp = run.value("pressure_drop");
    if (std::isfinite(dp)) {
      headline << ", pressure drop " << withError(dp, run.value("pressure_drop_err")) << " Pa";
      if (std::isfinite(frequency)) headline << " at " << core::humanNumber(frequency, 3) << " Hz";
      if (std::isfinite(amplitude)) headline << ", amplitude " << core::humanNumber(amplitude, 3) << " Pa";
      const double weight = run.value("bed_weight");
      if (std::isfinite(weight)) headline << " (bed weight " << core::humanNumber(weight, 4) << " Pa)";
    }
    if (std::isfinite(coordination)) headline << ", coordination " << core::humanNumber(coordination, 3);
    if (run.closure == "table") headline << ", the table covering " << coverage << " of the cell-steps / solids";
    if (std::isfinite(sp))
      headline << ", segregation percentage " << withError(sp, run.value("segregation_percentage_err"), 3) << " %";
    headline << ". ";
  }
  headline << "Time-averaged over each run's averaging window, errors by block averaging; deviation = (run − "
              "value) / value.";
  findings.headline = headline.str();
  return findings;
}

}  // namespace grainbridge::workflows::report
