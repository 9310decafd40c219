#pragma once
// A series' samples over an averaging window as summary values: <key> (the mean) and <key>_err
// (its block-averaging standard error, core/averaging/BlockAverage), as every bed stage reports.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/averaging/BlockAverage.hpp"

namespace grainbridge::workflows::stages {

// Nothing is written for no samples.
inline void addAverage(nlohmann::json& summary, const std::string& key, const std::vector<double>& samples) {
  if (samples.empty()) return;
  const auto avg = core::averaging::blockAverage(samples);
  summary[key] = avg.mean;
  summary[key + "_err"] = avg.standardError;
}

}  // namespace grainbridge::workflows::stages
