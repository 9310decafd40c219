#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>
#include <stdexcept>

#include "db/BusyError.hpp"
#include "db/Clock.hpp"
#include "db/Database.hpp"
#include "db/FileSystemKind.hpp"
#include "db/ProvenanceStore.hpp"
#include "tests/db/TestSupport.hpp"

namespace grainbridge::db {
namespace {

using test::countRows;
using test::sampleInvocation;
using test::sampleRun;
using test::TempDir;
using ::testing::HasSubstr;

TEST(Database, FreshDatabaseMigratesToLatestVersion) {
  TempDir dir;
  Database db = Database::open(dir / "nested/folders/gb.sqlite");  // parents are created
  EXPECT_GE(Database::latestSchemaVersion(), 1);
  EXPECT_EQ(db.schemaVersion(), Database::latestSchemaVersion());
  for (const char* table : {"invocations", "runs", "run_inputs", "artifacts", "stage_cache", "leases"})
    EXPECT_EQ(countRows(db, table), 0) << table;
  EXPECT_TRUE(db.path().is_absolute());
  EXPECT_EQ(db.integrityCheck(), "ok");
}

TEST(Database, ReopeningDoesNotMigrateAgain) {
  TempDir dir;
  {
    Database db = Database::open(dir / "gb.sqlite");
    ProvenanceStore(db).insertInvocation(sampleInvocation());
  }
  // Migration 1 is a plain CREATE TABLE: running it again would throw "table already exists".
  Database db = Database::open(dir / "gb.sqlite");
  EXPECT_EQ(db.schemaVersion(), Database::latestSchemaVersion());
  EXPECT_EQ(countRows(db, "invocations"), 1);
}

TEST(Database, RefusesSchemaNewerThanThisBuild) {
  TempDir dir;
  const auto path = dir / "gb.sqlite";
  const int newer = Database::latestSchemaVersion() + 7;
  Database::open(path).exec("PRAGMA user_version=" + std::to_string(newer));
  for (bool readOnly : {false, true}) {
    try {
      readOnly ? Database::openReadOnly(path) : Database::open(path);
      FAIL() << "a newer schema was accepted";
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr(path.string()));
      EXPECT_THAT(e.what(), HasSubstr("schema version " + std::to_string(newer)));
      EXPECT_THAT(e.what(), HasSubstr("version " + std::to_string(Database::latestSchemaVersion())));
    }
  }
}

TEST(Database, UsesWalOnLocalDiskAndEnforcesForeignKeys) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  ASSERT_FALSE(isOnNetworkFileSystem(dir.path())) << "the temp dir should be a local disk";
  EXPECT_EQ(db.journalMode(), "wal");
  Statement fk = db.prepare("PRAGMA foreign_keys");
  ASSERT_TRUE(fk.step());
  EXPECT_EQ(fk.columnInt64(0), 1);

  ArtifactRecord orphan{0, 12345, "k", "bed/k/particles.h5", "frames", "ab", 10};
  try {
    ProvenanceStore(db).addArtifact(orphan);
    FAIL() << "an artifact of a missing run was accepted";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("FOREIGN KEY"));
    EXPECT_THAT(e.what(), HasSubstr(db.path().string()));
  }
}

TEST(Database, RecognisesNetworkFileSystems) {
  for (std::uint64_t magic : {0x6969ULL, 0xFF534D42ULL, 0xFE534D42ULL, 0x0BD00BD0ULL, 0x47504653ULL, 0x19830326ULL})
    EXPECT_TRUE(isNetworkFileSystemMagic(magic)) << std::hex << magic;
  for (std::uint64_t magic :
       {0xEF53ULL /* ext4 */, 0x58465342ULL /* xfs */, 0x01021994ULL /* tmpfs */, 0x794C7630ULL /* overlayfs */})
    EXPECT_FALSE(isNetworkFileSystemMagic(magic)) << std::hex << magic;
}

TEST(Database, TransactionCommitsAndReturnsTheValue) {
  TempDir dir;
  const auto path = dir / "gb.sqlite";
  {
    Database db = Database::open(path);
    const std::int64_t id =
        db.transaction([](Database& d) { return ProvenanceStore(d).insertInvocation(sampleInvocation()); });
    EXPECT_GT(id, 0);
    EXPECT_FALSE(db.inTransaction());
  }
  Database db = Database::open(path);
  EXPECT_EQ(countRows(db, "invocations"), 1);
}

TEST(Database, ExceptionInsideTransactionRollsBackEverything) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  EXPECT_THROW(db.transaction([](Database& d) {
    ProvenanceStore store(d);
    const auto invocation = store.insertInvocation(sampleInvocation());
    const auto run = store.insertRun(sampleRun(invocation, "k1"));
    store.addArtifact({0, run, "k1", "bed/k1/a.h5", "frames", "00", 1});
    throw std::runtime_error("stage failed");
  }),
               std::runtime_error);
  EXPECT_FALSE(db.inTransaction());
  for (const char* table : {"invocations", "runs", "run_inputs", "artifacts"}) EXPECT_EQ(countRows(db, table), 0);
  // The connection is usable afterwards.
  db.transaction([](Database& d) { ProvenanceStore(d).insertInvocation(sampleInvocation()); });
  EXPECT_EQ(countRows(db, "invocations"), 1);
}

TEST(Database, FailedStatementInsideTransactionRollsBack) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  EXPECT_THROW(db.transaction([](Database& d) {
    ProvenanceStore store(d);
    store.insertInvocation(sampleInvocation());
    InvocationRecord bad = sampleInvocation();
    bad.status = "exploded";  // violates the CHECK constraint
    store.insertInvocation(bad);
  }),
               Error);
  EXPECT_EQ(countRows(db, "invocations"), 0);
}

TEST(DatabaseDeathTest, NestedTransactionIsAProgrammerError) {
  TempDir dir;
  EXPECT_DEATH(
      {
        Database db = Database::open(dir / "gb.sqlite");
        db.transaction([](Database& d) { d.transaction([](Database&) {}); });
      },
      "not reentrant");
}

TEST(Database, BusyWriteLockEndsInBusyErrorAfterRetries) {
  TempDir dir;
  const auto path = dir / "gb.sqlite";
  Database holder = Database::open(path);
  Database waiter = Database::open(path);
  holder.exec("BEGIN IMMEDIATE");
  waiter.setBusyTimeout(std::chrono::milliseconds(20));
  waiter.setBusyRetries(1);
  try {
    waiter.transaction([](Database&) {});
    FAIL() << "got the write lock while another connection held it";
  } catch (const BusyError& e) {
    EXPECT_THAT(e.what(), HasSubstr(path.string()));
    EXPECT_THAT(e.what(), HasSubstr("2 attempt(s)"));
  }
  EXPECT_FALSE(waiter.inTransaction());
  holder.exec("ROLLBACK");
  waiter.transaction([](Database& d) { ProvenanceStore(d).insertInvocation(sampleInvocation()); });
  EXPECT_EQ(countRows(holder, "invocations"), 1);
}

TEST(Database, OpeningAndReadingWhileAnotherConnectionWritesDoesNotWait) {
  TempDir dir;
  const auto path = dir / "gb.sqlite";
  Database writer = Database::open(path);
  writer.exec("BEGIN IMMEDIATE");
  ProvenanceStore(writer).insertInvocation(sampleInvocation());
  // A `grainbridge status` or the heartbeat's own connection opening mid-commit: in WAL
  // neither the open (schema already current) nor a read needs the write lock.
  const auto start = std::chrono::steady_clock::now();
  Database reader = Database::open(path);
  EXPECT_EQ(countRows(reader, "invocations"), 0);  // the uncommitted row is invisible
  Database readOnly = Database::openReadOnly(path);
  EXPECT_EQ(countRows(readOnly, "invocations"), 0);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  writer.exec("COMMIT");
  EXPECT_EQ(countRows(reader, "invocations"), 1);
}

TEST(Database, ReadOnlyOpenNeedsAnExistingFileAndRefusesWrites) {
  TempDir dir;
  const auto path = dir / "gb.sqlite";
  try {
    Database::openReadOnly(path);
    FAIL() << "opened a missing database";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr(path.string()));
    EXPECT_THAT(e.what(), HasSubstr("does not exist"));
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  Database::open(path).transaction([](Database& d) { ProvenanceStore(d).insertInvocation(sampleInvocation()); });

  Database reader = Database::openReadOnly(path);
  EXPECT_EQ(countRows(reader, "invocations"), 1);
  EXPECT_THROW(reader.exec("DELETE FROM invocations"), Error);
}

TEST(Database, StatementErrorsNameTheFileAndTheSql) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  try {
    db.prepare("SELEKT 1");
    FAIL();
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr(db.path().string()));
    EXPECT_THAT(e.what(), HasSubstr("SELEKT 1"));
  }
  Statement insert = db.prepare(
      "INSERT INTO leases(key, host, pid, pid_start, claimed_at, heartbeat_at) "
      "VALUES('k', NULL, 1, '1', 'x', 'x')");
  try {
    insert.step();
    FAIL();
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("NOT NULL"));
    EXPECT_THAT(e.what(), HasSubstr("INSERT INTO leases"));
  }
}

TEST(Database, StatementBindsAndReadsEveryType) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  Statement select = db.prepare("SELECT ?, ?, ?, ?, ?");
  select.bind(1, std::int64_t{1} << 40).bind(2, 0.25).bind(3, std::string("text\0with nul", 13)).bindNull(4).bind(5, 7);
  ASSERT_TRUE(select.step());
  EXPECT_EQ(select.columnInt64(0), std::int64_t{1} << 40);
  EXPECT_DOUBLE_EQ(select.columnDouble(1), 0.25);
  EXPECT_EQ(select.columnText(2), std::string("text\0with nul", 13));
  EXPECT_TRUE(select.columnIsNull(3));
  EXPECT_EQ(select.columnText(3), "");
  EXPECT_EQ(select.columnInt64(4), 7);
  EXPECT_FALSE(select.step());
  select.reset();
  EXPECT_TRUE(select.step());  // bindings survive reset
  EXPECT_EQ(select.columnInt64(4), 7);
}

TEST(Clock, FormatsIso8601UtcWithMillisecondsAndParsesBack) {
  const std::string now = nowUtc();
  EXPECT_TRUE(std::regex_match(now, std::regex(R"(\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}\.\d{3}Z)"))) << now;
  const auto parsed = parseUtc("2026-11-23T20:14:05.123Z");
  ASSERT_TRUE(parsed.has_value());
  EXPECT_EQ(formatUtc(*parsed), "2026-11-23T20:14:05.123Z");
  EXPECT_EQ(formatUtc(std::chrono::system_clock::time_point{}), "1970-01-01T00:00:00.000Z");
  EXPECT_FALSE(parseUtc("2026-11-23 20:14:05").has_value());
  EXPECT_FALSE(parseUtc("2026-13-23T20:14:05.123Z").has_value());
}

}  // namespace
}  // namespace grainbridge::db
