#pragma once
// A validated workflow config (DESIGN.md, "Configs (normative grammar)"):
//   { "name": str, "units"?: {"system": "SI" | "reduced", "d0"?, "m0"?, "g"?},
//     "database"?: path,
//     "stages": { <name>: { "type": str, "params"?: {...}, "from"?: str | [str],
//                           "sweep"?: {<param>: [values...]}, "ranks_per_instance"?: int } } }
// Loading checks everything before any work starts and reports every problem at once, each
// with its JSON pointer (or line and column for a syntax error).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/units/UnitSystem.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace grainbridge::workflows::config {

struct SweepAxis {
  std::string param;
  std::vector<nlohmann::json> values;  // resolved (SI), in the order given
  std::vector<nlohmann::json> written; // the same values as the config gives them ("13.7823 mm")
};

struct StageConfig {
  std::string name;
  const stages::StageType* type = nullptr;
  nlohmann::json params;  // resolved (SI, defaults filled), swept parameters excluded
  std::vector<std::string> from;
  std::vector<SweepAxis> sweep;  // Cartesian product: one instance per point
  int ranksPerInstance = 1;
};

struct WorkflowConfig {
  std::string name;
  core::units::UnitSystem units;
  std::filesystem::path database;   // as given, or results/<name>/grainbridge.sqlite
  std::vector<StageConfig> stages;  // in a topological order of `from`
  nlohmann::json document;          // the config as parsed, for provenance
  std::filesystem::path sourcePath;

  [[nodiscard]] const StageConfig* findStage(const std::string& stageName) const;
};

// The points of the Cartesian product of sweep axes, first axis slowest: {param: value}.
std::vector<nlohmann::json> sweepPoints(const std::vector<SweepAxis>& axes);
// The same points, in the same order, with each value as the config wrote it (for people).
std::vector<nlohmann::json> sweepPointsAsWritten(const std::vector<SweepAxis>& axes);
// `params` with a sweep point applied; a swept name with '/' is a path into nested
// parameters ("walls/1/mu").
nlohmann::json withSweepPoint(nlohmann::json params, const nlohmann::json& point);

// Throws core::json::InputError listing every problem found.
WorkflowConfig loadWorkflow(const std::filesystem::path& path, const stages::StageRegistry& registry);
WorkflowConfig parseWorkflow(const nlohmann::json& document, const std::string& sourceName,
                             const stages::StageRegistry& registry);

}  // namespace grainbridge::workflows::config
