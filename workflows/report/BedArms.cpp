#include "workflows/report/BedArms.hpp"

#include <cmath>
#include <sstream>

#include "core/text/NumberText.hpp"
#include "workflows/report/CsvField.hpp"
#include "workflows/report/SweepLabel.hpp"

namespace grainbridge::workflows::report {

namespace {

std::string number(double v) { return std::isfinite(v) ? core::roundTripText(v) : std::string(); }

// How the sentences name an output, its unit and the unit of a difference of two (s_p is in
// percent: two of them differ by percentage points).
struct OutputWords {
  std::string name, unit, difference;
};
const std::map<std::string, OutputWords> kWords = {{"segregation_percentage", {"s_p", " %", " percentage points"}},
                                                   {"mean_height", {"mean height", " m", " m"}}};

// The outputs an arm has a mean of, s_p first: the study's quantity where it is recorded.
std::vector<std::string> spokenOutputs(const BedArm& arm) {
  std::vector<std::string> out;
  for (const char* k : {"segregation_percentage", "mean_height"}) {
    if (std::isfinite(arm.outputs.at(k).mean)) out.emplace_back(k);
  }
  return out;
}

}  // namespace

std::vector<BedArm> bedArms(const std::vector<BedRun>& runs, const std::vector<Arm>& arms) {
  std::vector<BedArm> out;
  for (const Arm& arm : arms) {
    BedArm bedArm{arm, {}};
    for (const auto& output : kRealisedOutputs) {
      std::vector<double> values;
      for (const std::size_t r : arm.runs) {
        const BedRun& run = runs.at(r);
        values.push_back(output == "mean_height" ? run.meanHeight : run.value(output));
      }
      bedArm.outputs[output] = overRealisations(values);
    }
    out.push_back(std::move(bedArm));
  }
  return out;
}

std::string armsCsv(const std::vector<BedArm>& arms) {
  std::ostringstream csv;
  csv << "arm,realisations,realisation_values";
  for (const auto& output : kRealisedOutputs) csv << ',' << output << "_mean," << output << "_sd," << output << "_se";
  csv << '\n';
  for (const auto& a : arms) {
    std::string values;
    for (const auto& v : a.arm.realisations) values += (values.empty() ? "" : ";") + v;
    csv << csvField(a.arm.label) << ',' << a.arm.runs.size() << ',' << csvField(values);
    for (const auto& output : kRealisedOutputs) {
      const RealisationStatistics& s = a.outputs.at(output);
      csv << ',' << number(s.mean) << ',' << number(s.sd) << ',' << number(s.se);
    }
    csv << '\n';
  }
  return csv.str();
}

std::string armsHeadline(const std::vector<BedArm>& arms, const std::string& realisation) {
  std::ostringstream text;
  std::vector<Arm> grouped;
  for (const auto& a : arms) {
    grouped.push_back(a.arm);
    if (a.arm.runs.size() < 2) continue;
    text << a.arm.label << ":";
    const auto outputs = spokenOutputs(a);
    for (std::size_t k = 0; k < outputs.size(); ++k) {
      const RealisationStatistics& s = a.outputs.at(outputs[k]);
      const OutputWords& words = kWords.at(outputs[k]);
      text << (k == 0 ? " " : ", ") << words.name << ' ' << core::humanWithError(s.mean, s.se) << words.unit;
    }
    text << " (mean and standard error over " << a.arm.runs.size() << " realisations: " << parameterName(realisation)
         << ' ';
    for (std::size_t k = 0; k < a.arm.realisations.size(); ++k) text << (k == 0 ? "" : ", ") << a.arm.realisations[k];
    text << "). ";
  }
  // The difference one setting makes, the others held: what the spread over realisations is for.
  for (const auto& c : armContrasts(grouped)) {
    const BedArm &from = arms[c.from], &to = arms[c.to];
    nlohmann::json held = from.arm.written;
    held.erase(c.parameter);
    text << sweepLabel(from.arm.stage, held) << ": " << parameterName(c.parameter) << ' '
         << writtenText(from.arm.written.at(c.parameter)) << " → " << writtenText(to.arm.written.at(c.parameter));
    bool first = true;
    for (const auto& output : spokenOutputs(from)) {
      if (!std::isfinite(to.outputs.at(output).mean)) continue;
      const MeanDifference d = meanDifference(from.outputs.at(output), to.outputs.at(output));
      const OutputWords& words = kWords.at(output);
      text << (first ? " " : ", ") << (d.value >= 0 ? "raises " : "lowers ") << words.name << " by "
           << core::humanWithError(std::abs(d.value), d.se) << words.difference;
      if (std::isfinite(d.standardErrors())) {
        text << " (" << core::humanNumber(std::abs(d.standardErrors()), 2) << " standard errors)";
      }
      first = false;
    }
    const std::size_t n = from.arm.runs.size(), m = to.arm.runs.size();
    text << "; " << n << (n == m ? "" : " and " + std::to_string(m)) << " realisations" << (n == m ? " each" : "")
         << ". ";
  }
  return text.str();
}

}  // namespace grainbridge::workflows::report
