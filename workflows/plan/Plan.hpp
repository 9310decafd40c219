#pragma once
// Expands a workflow's stages into stage instances (one per sweep point and replica, and, for
// per-instance stages, per upstream instance) and gives each its stage key (DESIGN.md, workflow semantics):
//   key = sha256(type, impl_version, canonical resolved params, upstream keys)
// Canonical params are SI values with defaults filled in, keys sorted, floats in shortest
// round-trip text, parameters declared not to affect results left out. Paths, hosts, git SHA
// and rank counts never enter, so a docs-only commit or a moved project invalidates nothing.
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "workflows/config/WorkflowConfig.hpp"
#include "workflows/stages/PlannedOutput.hpp"
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::plan {

struct StageInstance {
  std::size_t index = 0;  // position in Plan::instances
  std::string stage;
  const stages::StageType* type = nullptr;
  nlohmann::json params;      // resolved, sweep point and replica overlay merged in
  nlohmann::json sweepPoint;  // {param: value} of this instance ({} without a sweep)
  nlohmann::json sweepWritten;  // the same point as the config wrote it ("13.7823 mm")
  stages::Replica replica;      // which copy of its sweep point it is (StageType::replicas)
  std::string key;
  std::vector<std::size_t> upstream;  // indices of the instances it consumes
  int ranks = 1;
  // The closure tables it reads (StageType::closureTables): made by the upstream instance of
  // `runKey` (a tabulate stage in `from`), or found in the database with content `sha256`.
  struct TableInput {
    std::string name, quantity;
    std::string runKey;
    std::string sha256;
  };
  std::vector<TableInput> tables;

  // "gas" or "gas[solid_fraction=0.1, box=13.7 mm (×3)]" (values as written, then what tells a
  // replica apart: "bed[closure_sample=3]"), for logs and status.
  [[nodiscard]] std::string label() const;
  // <workflow>/<stage>/<key>: the instance folder relative to the results root.
  [[nodiscard]] std::string relativeDir(const std::string& workflow) const;
};

struct Plan {
  std::string workflow;
  std::vector<StageInstance> instances;  // topological order
  std::map<std::string, std::vector<std::size_t>> byStage;
};

// The newest closure table `name` of `quantity` in the workflow database as the plan needs it:
// its content hash ("" when the database has none) and, where the database records them, the
// grains it was made from.
struct TableFound {
  std::string sha256;
  std::optional<stages::Grains> grains;
  bool hasErrors = false;  // the database holds each node's standard error
};
using TableLookup = std::function<TableFound(const std::string& name, const std::string& quantity)>;

// Throws grainbridge::Error naming the stage parameter when an instance reads a closure table
// that neither a tabulate stage in its `from` makes nor the database (`lookup`) holds, or one the
// stage refuses for its grains (StageType::checkTableGrains).
Plan makePlan(const config::WorkflowConfig& config, const TableLookup& lookup = {});

// The canonical text that is hashed into a stage key (exposed for `status --why` and tests).
// `tables` ({"name/quantity": sha256 or "upstream"}) enters only when not empty, so stages that
// read no table keep their keys.
nlohmann::json keyMaterial(const stages::StageType& type, const nlohmann::json& resolvedParams,
                           const std::vector<std::string>& upstreamKeys,
                           const nlohmann::json& tables = nlohmann::json::object());
std::string stageKey(const nlohmann::json& keyMaterial);

}  // namespace grainbridge::workflows::plan
