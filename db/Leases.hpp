#pragma once
// A stage instance is claimed with a lease row instead of a lock file, so a killed run leaves
// nothing to clean by hand. A lease is live while its holder process is alive: on the same
// host, /proc/<pid> exists and its start time (field 22 of /proc/<pid>/stat, stored as text in
// pid_start, guarding against pid reuse) matches; on another host, where we cannot look at its
// processes, its heartbeat is younger than staleAfter. A dead holder's lease is taken over.
// Methods open no transaction; claim() is nevertheless race-free on its own (insert-if-absent
// and compare-and-swap takeover), so two claimers can never both win.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "db/Records.hpp"

namespace grainbridge::db {

class Database;

std::string hostName();
// Start time of a running process (field 22 of /proc/<pid>/stat, in clock ticks since boot);
// nullopt if there is no such process or it is a zombie (it exited and will never finish).
std::optional<std::string> liveProcessStartTime(std::int64_t pid);
// host = gethostname, pid = getpid, pidStart from /proc/self/stat.
LeaseHolder currentProcessHolder(std::int64_t runId);
// See the file comment. Other hosts are judged by heartbeat age, so clocks must agree to well
// within staleAfter (NTP on a cluster does).
bool isHolderAlive(const LeaseHolder& holder, const std::string& heartbeatAt, std::chrono::seconds staleAfter);

class Leases {
 public:
  struct ClaimResult {
    bool claimed = false;
    std::optional<LeaseHolder> liveHolder;  // set when someone alive holds it
  };

  explicit Leases(Database& db);

  // Claims `key` for `me` (me.runId 0 = no run yet, stored as NULL). Succeeds if the key is
  // free, already held by this same process (heartbeat refreshed, run id updated if given),
  // or held by a dead holder (taken over).
  ClaimResult claim(const std::string& key, const LeaseHolder& me, std::chrono::seconds staleAfter);
  void heartbeat(const std::string& key, const LeaseHolder& me);  // updates heartbeat_at if still mine
  void release(const std::string& key, const LeaseHolder& me);    // no-op if not mine
  // Records the run a held lease is executing (so orphaned runs can be found); false if the
  // lease is no longer mine.
  bool setRun(const std::string& key, const LeaseHolder& me, std::int64_t runId);
  std::optional<LeaseHolder> holder(const std::string& key);
  std::vector<std::pair<std::string, LeaseHolder>> deadLeases(std::chrono::seconds staleAfter);

 private:
  Database& db_;
};

}  // namespace grainbridge::db
