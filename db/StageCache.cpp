#include "db/StageCache.hpp"

#include "db/Clock.hpp"
#include "db/Database.hpp"

namespace grainbridge::db {

namespace {
constexpr const char* kColumns = "key, run_id, workflow, stage, instance_dir, completed_at";

CacheEntry readEntry(const Statement& row) {
  return CacheEntry{row.columnText(0), row.columnInt64(1), row.columnText(2),
                    row.columnText(3), row.columnText(4),  row.columnText(5)};
}
}  // namespace

StageCache::StageCache(Database& db) : db_(db) {}

std::optional<CacheEntry> StageCache::lookup(const std::string& key) {
  Statement query = db_.prepare(std::string("SELECT ") + kColumns + " FROM stage_cache WHERE key=?");
  query.bind(1, key);
  if (!query.step()) return std::nullopt;
  return readEntry(query);
}

void StageCache::record(const CacheEntry& entry) {
  Statement insert =
      db_.prepare(std::string("INSERT OR REPLACE INTO stage_cache(") + kColumns + ") VALUES(?,?,?,?,?,?)");
  insert.bind(1, entry.key)
      .bind(2, entry.runId)
      .bind(3, entry.workflow)
      .bind(4, entry.stage)
      .bind(5, entry.instanceDir)
      .bind(6, entry.completedAt.empty() ? nowUtc() : entry.completedAt);
  insert.step();
}

void StageCache::invalidate(const std::string& key) {
  Statement remove = db_.prepare("DELETE FROM stage_cache WHERE key=?");
  remove.bind(1, key);
  remove.step();
}

std::vector<CacheEntry> StageCache::entries(const std::string& workflow) {
  Statement query = db_.prepare(std::string("SELECT ") + kColumns + " FROM stage_cache" +
                                (workflow.empty() ? "" : " WHERE workflow=?") + " ORDER BY workflow, stage, key");
  if (!workflow.empty()) query.bind(1, workflow);
  std::vector<CacheEntry> result;
  while (query.step()) result.push_back(readEntry(query));
  return result;
}

}  // namespace grainbridge::db
