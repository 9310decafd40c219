#include <gtest/gtest.h>

#include "db/Database.hpp"
#include "db/ProvenanceStore.hpp"
#include "db/StageCache.hpp"
#include "tests/db/TestSupport.hpp"

namespace grainbridge::db {
namespace {

using test::sampleInvocation;
using test::sampleRun;
using test::TempDir;

TEST(StageCache, RecordLookupReplaceInvalidate) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  ProvenanceStore store(db);
  StageCache cache(db);
  const auto invocationId = store.insertInvocation(sampleInvocation());
  const auto run1 = store.insertRun(sampleRun(invocationId, "k1"));
  const auto run2 = store.insertRun(sampleRun(invocationId, "k1"));
  const auto run3 = store.insertRun(sampleRun(invocationId, "k2", "other"));

  EXPECT_FALSE(cache.lookup("k1").has_value());
  const CacheEntry entry{"k1", run1, "shear", "bed", "bed/k1", "2026-11-23T20:14:05.123Z"};
  db.transaction([&](Database&) { cache.record(entry); });
  ASSERT_TRUE(cache.lookup("k1").has_value());
  EXPECT_EQ(*cache.lookup("k1"), entry);

  // A forced rerun replaces the entry; an empty completedAt means now.
  cache.record(CacheEntry{"k1", run2, "shear", "bed", "bed/k1", ""});
  const CacheEntry replaced = *cache.lookup("k1");
  EXPECT_EQ(replaced.runId, run2);
  EXPECT_FALSE(replaced.completedAt.empty());

  cache.record(CacheEntry{"k2", run3, "other", "bed", "bed/k2", ""});
  EXPECT_EQ(cache.entries("shear").size(), 1u);
  EXPECT_EQ(cache.entries("").size(), 2u);

  cache.invalidate("k1");
  EXPECT_FALSE(cache.lookup("k1").has_value());
  EXPECT_TRUE(cache.entries("shear").empty());
  cache.invalidate("k1");                                                                   // absent: no-op
  EXPECT_THROW(cache.record(CacheEntry{"k3", 9999, "shear", "bed", "bed/k3", ""}), Error);  // no such run
}

}  // namespace
}  // namespace grainbridge::db
