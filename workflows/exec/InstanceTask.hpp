#pragma once
// Everything a rank needs to run one stage instance, and what it hands back. The serial
// executor hands the task itself to InstanceRunner; the MPI executor sends it to a worker as
// JSON (toJson, fromJson), the one conversion the rank boundary forces. Either way InstanceRunner
// runs it, and only rank 0 ever writes the database.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/LoadedClosureTable.hpp"
#include "core/LoadedRheology.hpp"

namespace grainbridge::workflows::exec {

struct UpstreamRef {
  std::string stage;
  std::string stageType;
  std::string key;
  std::string dir;  // instance folder relative to the results root
  // Its sweep point as the plan gives it (UpstreamInstance::setSweep), SI and as written.
  nlohmann::json sweepPoint = nlohmann::json::object();
  nlohmann::json sweepWritten = nlohmann::json::object();
};

struct InstanceTask {
  std::string workflow;
  std::string stage;
  std::string stageType;
  std::string key;
  nlohmann::json params;
  nlohmann::json sweepPoint;
  nlohmann::json sweepWritten;  // the point as the config wrote it (for the report)
  std::string database;         // the workflow database path (for the report's footer)
  std::vector<UpstreamRef> upstream;
  nlohmann::json units;
  std::string instanceDir;  // relative to the results root
  std::vector<int> group;   // world ranks running it together (MPI executor)
  // The closure tables the stage reads, as db::ClosureStore::loadTable gives them (rank 0 loads
  // them: workers never open the database).
  std::vector<core::LoadedClosureTable> closureTables;
  // The mu(I) rheologies it reads (ClosureTableRef of quantity mu_of_I), as
  // db::ClosureStore::loadRheology gives them.
  std::vector<core::LoadedRheology> rheologies;

  // For an MPI worker. fromJson throws grainbridge::Error naming what is missing or wrong in a
  // table (core::loadedClosureTableFromJson).
  [[nodiscard]] nlohmann::json toJson() const;
  static InstanceTask fromJson(const nlohmann::json& j);
};

struct InstanceOutcome {
  enum class Status { Done, Failed, Interrupted };
  Status status = Status::Failed;
  std::string error;
  nlohmann::json manifest;  // for Done: artifacts with sha256 and bytes, summary, timing

  [[nodiscard]] nlohmann::json toJson() const;
  static InstanceOutcome fromJson(const nlohmann::json& j);
};

}  // namespace grainbridge::workflows::exec
