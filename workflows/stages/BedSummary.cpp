#include "workflows/stages/BedSummary.hpp"

#include "core/averaging/DominantFrequency.hpp"
#include "workflows/stages/SummaryAverage.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;

void addTapSummary(json& summary, const std::vector<PressureTap>& taps,
                   const std::map<std::string, std::vector<double>>& window, const std::vector<double>& times) {
  for (std::size_t k = 0; k < taps.size(); ++k) {
    const std::string column = "dp_" + taps[k].name;
    addAverage(summary, column, window.at(column));
    if (k == 0) addAverage(summary, "pressure_drop", window.at(column));
    // The fluctuation's dominant frequency and amplitude over the window (Fig. 7.3), at the
    // rows' own times.
    if (const auto spectrum = core::averaging::dominantFrequency(times, window.at(column))) {
      summary[column + "_frequency"] = spectrum->frequency;
      summary[column + "_amplitude"] = spectrum->amplitude;
    }
  }
  if (!taps.empty()) summary["pressure_drop_tap"] = taps.front().name;
}

void addTapPlannedOutput(PlannedOutput& out, const json& params) {
  bool first = true;
  for (const auto& tap : params.value("pressure_taps", json::array())) {
    if (first) {
      out.summaryKeys.push_back("pressure_drop");
      out.summaryKeys.push_back("pressure_drop_tap");
      first = false;
    }
    out.summaryKeys.push_back("dp_" + tap.at("name").get<std::string>());
    out.seriesColumns.push_back("dp_" + tap.at("name").get<std::string>());
  }
}

}  // namespace grainbridge::workflows::stages
