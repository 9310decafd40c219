#pragma once
// Reads and writes the provenance tables (invocations, runs, run_inputs, artifacts). It opens
// no transaction itself: a stage completion (finishRun + artifacts + cache entry + lease
// release) must commit as one unit, so the caller wraps the calls in Database::transaction.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "db/Records.hpp"

namespace grainbridge::db {

class Database;

class ProvenanceStore {
 public:
  explicit ProvenanceStore(Database& db);

  // Empty status -> "running", empty startedAt -> now. Returns the new id.
  std::int64_t insertInvocation(const InvocationRecord& invocation);
  // Sets status and ended_at = now. Throws if no such invocation.
  void finishInvocation(std::int64_t id, const std::string& status);

  // Also inserts run.upstreamKeys into run_inputs. Defaults as insertInvocation.
  std::int64_t insertRun(const RunRecord& run);
  // Sets status, error, summary_json ("" -> NULL) and ended_at = now. Throws if no such run.
  void finishRun(std::int64_t runId, const std::string& status, const std::string& error,
                 const std::string& summaryJson);

  void addArtifact(const ArtifactRecord& artifact);
  std::vector<ArtifactRecord> artifactsOfRun(std::int64_t runId);

  std::optional<RunRecord> run(std::int64_t id);
  std::vector<RunRecord> runs(const std::string& workflow);                // "" = all workflows; by id
  std::vector<RunRecord> runsOfKey(const std::string& key);                // by id (oldest first)
  std::vector<InvocationRecord> invocations(const std::string& workflow);  // "" = all; by id

  // Marks runs still 'running' whose lease is gone or whose lease holder is dead (see
  // isHolderAlive) as 'killed', with error "process <host>:<pid> ended without finishing".
  // A run is matched to its lease by leases.run_id, or, while run_id is unset, by the lease
  // key, host and pid. Returns how many runs were marked.
  int markOrphanedRunsKilled(std::chrono::seconds staleAfter);

 private:
  std::vector<std::string> upstreamKeysOf(std::int64_t runId);
  std::vector<RunRecord> queryRuns(const std::string& where, const std::string& argument);

  Database& db_;
};

}  // namespace grainbridge::db
