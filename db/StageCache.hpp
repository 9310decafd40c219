#pragma once
// Completed stage instances by key, so a later invocation can skip them. Whether an entry is
// still valid (artifacts present with matching sha256) is the workflow's decision; this class
// only stores it. Like the other stores, it opens no transaction: recording an entry belongs
// in the same transaction as the run it completes.
#include <optional>
#include <string>
#include <vector>

#include "db/Records.hpp"

namespace grainbridge::db {

class Database;

class StageCache {
 public:
  explicit StageCache(Database& db);

  std::optional<CacheEntry> lookup(const std::string& key);
  // Insert or replace (a forced rerun supersedes the old entry). Empty completedAt -> now.
  void record(const CacheEntry& entry);
  void invalidate(const std::string& key);                       // no-op if absent
  std::vector<CacheEntry> entries(const std::string& workflow);  // "" = all; by workflow, stage, key

 private:
  Database& db_;
};

}  // namespace grainbridge::db
