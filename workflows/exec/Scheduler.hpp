#pragma once
// `grainbridge run`: walks the plan, skips instances with a valid completed record, claims and
// dispatches the rest as soon as their upstream instances are done, and records each outcome.
// Only rank 0 calls this; other ranks run runMpiWorker.
#include <chrono>
#include <filesystem>

#include "workflows/config/WorkflowConfig.hpp"
#include "workflows/exec/Dispatcher.hpp"
#include "workflows/plan/Plan.hpp"

namespace grainbridge::workflows::exec {

struct RunOptions {
  bool force = false;      // rerun instances even when cached
  bool keepGoing = false;  // after a failure, still run every instance that does not depend on it
  std::filesystem::path workDir = ".";
  std::chrono::seconds staleAfter{120};  // a lease of another host without heartbeat this long is dead
  std::chrono::milliseconds heartbeatPeriod{10000};
};

struct RunSummary {
  int ran = 0;     // completed in this run
  int cached = 0;  // skipped: valid completed record
  int failed = 0;  // failed or interrupted in this run
  int notRun = 0;  // blocked by a failed upstream, or not started after a failure/stop
  int busy = 0;    // held by another live process
  bool interrupted = false;
  [[nodiscard]] int exitCode() const { return (failed > 0 || notRun > 0 || busy > 0 || interrupted) ? 1 : 0; }
};

RunSummary runWorkflow(const config::WorkflowConfig& config, const plan::Plan& plan, const RunOptions& options,
                       Dispatcher& dispatcher, int ranks);

// The results root (<workDir>/results) and the database path of a workflow.
std::filesystem::path resultsRoot(const std::filesystem::path& workDir);
std::filesystem::path databasePath(const config::WorkflowConfig& config, const std::filesystem::path& workDir);

}  // namespace grainbridge::workflows::exec
