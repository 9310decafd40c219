#pragma once
// How a comparison names a run by its sweep point as the config wrote it: "bed (gas_inflow
// 1.92 m/s, rotation_model true)". The run labels and the arms' labels (report/Realisations)
// are made here, so an arm reads as its runs' label without the realisation.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace grainbridge::workflows::report {

// A JSON value as a sweep entry writes it: strings verbatim, the rest as JSON text.
inline std::string writtenText(const nlohmann::json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

// A swept parameter as a label names it: the last component of its pointer
// ("boundaries/0/gas_inflow" reads "gas_inflow").
inline std::string parameterName(const std::string& pointer) {
  const auto slash = pointer.rfind('/');
  return slash == std::string::npos ? pointer : pointer.substr(slash + 1);
}

// "rotation_model true" per swept parameter, in the point's order.
inline std::vector<std::string> sweepParts(const nlohmann::json& written) {
  std::vector<std::string> parts;
  for (const auto& [k, v] : written.items()) parts.push_back(parameterName(k) + " " + writtenText(v));
  return parts;
}

// "<stage> (<part>, <part>)", or the stage alone when it was not swept.
inline std::string sweepLabel(const std::string& stage, const nlohmann::json& written) {
  std::string sweep;
  for (const auto& part : sweepParts(written)) sweep += (sweep.empty() ? "" : ", ") + part;
  return stage + (sweep.empty() ? "" : " (" + sweep + ")");
}

}  // namespace grainbridge::workflows::report
