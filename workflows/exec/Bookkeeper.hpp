#pragma once
// Rank 0's side of a run: the only code that writes the database. It records the invocation,
// decides whether an instance is cached (a completed record whose every artifact still has its
// sha256), claims instances with leases (kept fresh by a heartbeat thread), and records each
// outcome in one transaction, so a killed run never leaves half a record.
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "db/Database.hpp"
#include "db/Heartbeat.hpp"
#include "db/Records.hpp"
#include "workflows/config/WorkflowConfig.hpp"
#include "workflows/exec/InstanceTask.hpp"
#include "workflows/plan/Plan.hpp"

namespace grainbridge::workflows::exec {

class Bookkeeper {
 public:
  Bookkeeper(db::Database& database, const config::WorkflowConfig& config, std::filesystem::path resultsRoot, int ranks,
             std::chrono::seconds staleAfter, std::chrono::milliseconds heartbeatPeriod);
  ~Bookkeeper();
  Bookkeeper(const Bookkeeper&) = delete;
  Bookkeeper& operator=(const Bookkeeper&) = delete;

  // Records this invocation and marks runs of dead processes as killed. Returns how many.
  int start();
  // The completed record of this key if it is still valid; otherwise nullopt and, if asked,
  // the reason ("artifact frames/x.h5 changed on disk").
  std::optional<db::CacheEntry> validCacheEntry(const std::string& key, std::string* whyNot = nullptr);

  struct Begun {
    bool claimed = false;
    std::int64_t runId = 0;
    std::string holder;  // "host:pid" of the live process holding it, when not claimed
  };
  Begun begin(const plan::StageInstance& instance, const InstanceTask& task, int rank, int ranks);
  // Records how an instance ended. A Done outcome whose results the database refuses (the
  // closure rows it reported) becomes Failed, with the reason in outcome.error.
  void record(const plan::StageInstance& instance, const InstanceTask& task, std::int64_t runId,
              InstanceOutcome& outcome);
  void finish(const std::string& status);

 private:
  void recordDone(const plan::StageInstance& instance, const InstanceTask& task, std::int64_t runId,
                  const InstanceOutcome& outcome, const db::LeaseHolder& me);
  db::Database& db_;
  const config::WorkflowConfig& config_;
  std::filesystem::path resultsRoot_;
  int ranks_;
  std::chrono::seconds staleAfter_;
  std::chrono::milliseconds heartbeatPeriod_;
  std::int64_t invocationId_ = 0;
  std::unique_ptr<db::Heartbeat> heartbeat_;
};

}  // namespace grainbridge::workflows::exec
