#pragma once
// How a comparison names a run by its sweep point as the config wrote it: "bed (gas_inflow
// 1.92 m/s, rotation_model true)". The run labels and the arms' labels (report/Realisations)
// are made here, so an arm reads as its runs' label without the realisation; and the short
// labels of legends and axes, which name only what differs between the runs compared.
#include <algorithm>
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

// A run as a comparison names it: its stage and its sweep point as the config wrote it.
struct SweptRun {
  std::string stage;
  nlohmann::json written;
};

// Per run, what tells it from the others compared: its sweep parts ("rotation_model true") that
// not every run shares, after its stage's name where the runs come from several stages; its
// stage's name alone when nothing differs (a single run, or runs swept alike).
inline std::vector<std::vector<std::string>> distinguishingParts(const std::vector<SweptRun>& runs) {
  std::vector<std::vector<std::string>> parts;
  for (const auto& run : runs) parts.push_back(sweepParts(run.written));
  const auto everyRunHas = [&](const std::string& part) {
    for (const auto& p : parts) {
      if (std::find(p.begin(), p.end(), part) == p.end()) return false;
    }
    return true;
  };
  const bool stagesDiffer =
      std::any_of(runs.begin(), runs.end(), [&](const SweptRun& r) { return r.stage != runs.front().stage; });
  std::vector<std::vector<std::string>> out;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    std::vector<std::string> distinct;
    if (stagesDiffer) distinct.push_back(runs[r].stage);
    for (const auto& part : parts[r]) {
      if (!everyRunHas(part)) distinct.push_back(part);
    }
    if (distinct.empty()) distinct.push_back(runs[r].stage);
    out.push_back(std::move(distinct));
  }
  return out;
}

// "<stage> (<part>, <part>)", or the stage alone when it was not swept.
inline std::string sweepLabel(const std::string& stage, const nlohmann::json& written) {
  std::string sweep;
  for (const auto& part : sweepParts(written)) sweep += (sweep.empty() ? "" : ", ") + part;
  return stage + (sweep.empty() ? "" : " (" + sweep + ")");
}

}  // namespace grainbridge::workflows::report
