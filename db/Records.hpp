#pragma once
// Plain rows of the provenance tables, as the stores read and write them. Optional TEXT
// columns (ended_at, error, summary_json, config_path) map NULL <-> "". Paths (instanceDir,
// ArtifactRecord::path) are relative to the results root so a moved project stays valid.
#include <cstdint>
#include <string>
#include <vector>

namespace grainbridge::db {

// One `grainbridge run` (or other command) of one workflow.
struct InvocationRecord {
  std::int64_t id = 0;
  std::string workflow, configPath, configJson, codeVersion;
  bool codeDirty = false;
  std::string host;
  std::int64_t pid = 0;
  int ranks = 1;
  std::string startedAt, endedAt, status;  // status: running | done | failed | killed
  bool operator==(const InvocationRecord&) const = default;
};

// One execution of one stage instance; several runs may share a key (reruns, --force).
struct RunRecord {
  std::int64_t id = 0;
  std::int64_t invocationId = 0;
  std::string workflow, stage, stageType;
  int implVersion = 0;
  std::string key, paramsJson, instanceDir, codeVersion;
  bool codeDirty = false;
  std::string host;
  std::int64_t pid = 0;
  int rank = 0;
  int ranks = 1;
  std::string startedAt, endedAt, status, error, summaryJson;
  std::vector<std::string> upstreamKeys;  // run_inputs, in insertion order
  bool operator==(const RunRecord&) const = default;
};

struct ArtifactRecord {
  std::int64_t id = 0;
  std::int64_t runId = 0;
  std::string key, path, kind, sha256;
  std::int64_t bytes = 0;
  bool operator==(const ArtifactRecord&) const = default;
};

// A completed stage instance that later invocations may skip.
struct CacheEntry {
  std::string key;
  std::int64_t runId = 0;
  std::string workflow, stage, instanceDir, completedAt;
  bool operator==(const CacheEntry&) const = default;
};

// Who holds a lease: the process identity (host, pid, and the pid's start time so a reused
// pid is not mistaken for the holder) and, once known, the run it is executing (0 = none).
struct LeaseHolder {
  std::string host;
  std::int64_t pid = 0;
  std::string pidStart;
  std::int64_t runId = 0;
  bool operator==(const LeaseHolder&) const = default;
  // Same process, whatever run it is on.
  bool sameProcess(const LeaseHolder& other) const {
    return host == other.host && pid == other.pid && pidStart == other.pidStart;
  }
};

}  // namespace grainbridge::db
