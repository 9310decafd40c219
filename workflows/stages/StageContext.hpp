#pragma once
// What a stage instance sees while it runs: its resolved parameters (SI), the folder it writes
// into (the instance's `<key>.partial/`, renamed into place by the executor only when the stage
// returns), its upstream instances, a communicator, and a way to report artifacts and a
// summary. A stage never touches the database: the executor records what it reports, so the
// same stage code runs under the serial and the MPI executor.
#include <atomic>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/LoadedClosureTable.hpp"
#include "core/LoadedRheology.hpp"
#include "core/parallel/Communicator.hpp"
#include "core/units/UnitSystem.hpp"
#include "workflows/contract/Findings.hpp"
#include "workflows/contract/UpstreamInstance.hpp"
#include "workflows/driver/InstanceRun.hpp"

namespace grainbridge::workflows::stages {

// What a stage reads of its upstream instances, and how it registers its own files: the
// contract header report/ shares (workflows/contract/UpstreamInstance.hpp).
using contract::ArtifactEntry;
using contract::UpstreamInstance;

using driver::StageInterrupted;

// The instance's run (driver::InstanceRun: stage, key, output folder, ranks, stop flag, artifacts)
// with what a stage reads and records besides.
class StageContext : public driver::InstanceRun {
 public:
  StageContext(std::string workflow, std::string stage, std::string key, nlohmann::json params,
               std::filesystem::path outputDir, std::vector<UpstreamInstance> inputs,
               core::parallel::Communicator& comm, core::units::UnitSystem units, const std::atomic<bool>& stopFlag)
      : InstanceRun(std::move(stage), std::move(key), std::move(outputDir), comm, stopFlag),
        workflow_(std::move(workflow)),
        params_(std::move(params)),
        inputs_(std::move(inputs)),
        units_(units) {}

  [[nodiscard]] const std::string& workflow() const { return workflow_; }
  [[nodiscard]] const nlohmann::json& params() const { return params_; }
  // Where outputDir() is renamed to once the stage completes (for relative links).
  [[nodiscard]] std::filesystem::path publishedDir() const {
    std::string s = outputDir().string();
    if (s.size() > kPartialSuffix.size() && s.ends_with(kPartialSuffix)) s.resize(s.size() - kPartialSuffix.size());
    return s;
  }
  static constexpr std::string_view kPartialSuffix = ".partial";
  [[nodiscard]] const std::vector<UpstreamInstance>& inputs() const { return inputs_; }
  [[nodiscard]] const core::units::UnitSystem& units() const { return units_; }

  // Deterministic results worth showing in status and reports (no timings, no hosts).
  void setSummary(nlohmann::json summary) { summary_ = std::move(summary); }

  // The closure tables the stage declared (StageType::closureTables), loaded by the executor
  // through db::ClosureStore::loadTable, once per run.
  void setClosureTables(std::vector<core::LoadedClosureTable> tables) { closureTables_ = std::move(tables); }
  [[nodiscard]] const std::vector<core::LoadedClosureTable>& closureTables() const { return closureTables_; }
  // The mu(I) rheologies it declared (closureTables' refs of quantity mu_of_I), loaded the same way.
  void setRheologies(std::vector<core::LoadedRheology> rheologies) { rheologies_ = std::move(rheologies); }
  [[nodiscard]] const std::vector<core::LoadedRheology>& rheologies() const { return rheologies_; }
  // The workflow database's path, for a report to name (a stage never opens it).
  void setDatabasePath(std::string path) { databasePath_ = std::move(path); }
  [[nodiscard]] const std::string& databasePath() const { return databasePath_; }

  // What a comparing stage found (headline, table, figures): the report leads with it.
  void setFindings(contract::Findings findings) { findings_ = std::move(findings); }
  [[nodiscard]] const contract::Findings& findings() const { return findings_; }

  // Rows for the closure database (db::ClosureStore::recordTables(): closure_points,
  // force_statistics, structure_statistics, closure_tables), keyed by column name. They travel
  // in manifest.json and the executor inserts them in the transaction that marks the run done.
  void addRecord(const std::string& table, nlohmann::json row) { records_[table].push_back(std::move(row)); }
  [[nodiscard]] const nlohmann::json& records() const { return records_; }
  [[nodiscard]] const nlohmann::json& summary() const { return summary_; }

 private:
  std::string workflow_;
  nlohmann::json params_;
  std::vector<UpstreamInstance> inputs_;
  core::units::UnitSystem units_;
  nlohmann::json summary_ = nlohmann::json::object();
  nlohmann::json records_ = nlohmann::json::object();
  contract::Findings findings_;
  std::string databasePath_;
  std::vector<core::LoadedClosureTable> closureTables_;
  std::vector<core::LoadedRheology> rheologies_;
};

}  // namespace grainbridge::workflows::stages
