#pragma once
// Everything a rank needs to run one stage instance, and what it hands back. Both travel as
// JSON, so the serial executor and MPI workers share one code path (InstanceRunner) and only
// rank 0 ever writes the database.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

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
  // The closure tables the stage reads, as db::ClosureStore::loadTable gives them, in JSON (rank 0
  // loads them: workers never open the database).
  nlohmann::json closureTables = nlohmann::json::array();
  // The mu(I) rheologies it reads (ClosureTableRef of quantity mu_of_I), as
  // db::ClosureStore::loadRheology gives them, in JSON.
  nlohmann::json rheologies = nlohmann::json::array();

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
