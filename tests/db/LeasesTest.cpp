#include <gtest/gtest.h>

#include <thread>

#include "db/Clock.hpp"
#include "db/Database.hpp"
#include "db/Heartbeat.hpp"
#include "db/Leases.hpp"
#include "tests/db/TestSupport.hpp"

namespace grainbridge::db {
namespace {

using namespace std::chrono_literals;
using test::deadHolder;
using test::TempDir;

constexpr std::chrono::seconds kStale = 60s;

std::string heartbeatOf(Database& db, const std::string& key) {
  Statement read = db.prepare("SELECT heartbeat_at FROM leases WHERE key=?");
  read.bind(1, key);
  return read.step() ? read.columnText(0) : std::string();
}

void setHeartbeat(Database& db, const std::string& key, const std::string& when) {
  Statement update = db.prepare("UPDATE leases SET heartbeat_at=? WHERE key=?");
  update.bind(1, when).bind(2, key);
  update.step();
}

TEST(Leases, CurrentProcessHolderIsAlive) {
  const LeaseHolder me = currentProcessHolder(7);
  EXPECT_EQ(me.pid, ::getpid());
  EXPECT_EQ(me.host, hostName());
  EXPECT_EQ(me.runId, 7);
  EXPECT_FALSE(me.pidStart.empty());
  EXPECT_TRUE(isHolderAlive(me, "", kStale));  // same host: /proc decides, not the heartbeat
}

TEST(Leases, ExitedProcessOrWrongStartTimeIsDead) {
  EXPECT_FALSE(isHolderAlive(deadHolder(), nowUtc(), kStale));
  LeaseHolder reused = currentProcessHolder(0);
  reused.pidStart = "1";  // our pid, but someone else's start time: a reused pid
  EXPECT_FALSE(isHolderAlive(reused, nowUtc(), kStale));
}

TEST(Leases, UnreapedZombieIsDead) {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  // Until waitpid, /proc/<pid> stays (state Z); it must not count as a live holder.
  bool sawZombieAsDead = false;
  for (int i = 0; i < 500 && !sawZombieAsDead; ++i) {
    sawZombieAsDead = !liveProcessStartTime(pid).has_value();
    if (!sawZombieAsDead) std::this_thread::sleep_for(2ms);
  }
  EXPECT_TRUE(std::filesystem::exists("/proc/" + std::to_string(pid)));
  ::waitpid(pid, nullptr, 0);
  EXPECT_TRUE(sawZombieAsDead);
}

TEST(Leases, OtherHostHolderIsAliveWhileItsHeartbeatIsFresh) {
  const LeaseHolder remote{"elsewhere.invalid", 1, "12345", 0};
  const auto now = std::chrono::system_clock::now();
  EXPECT_TRUE(isHolderAlive(remote, formatUtc(now), kStale));
  EXPECT_TRUE(isHolderAlive(remote, formatUtc(now - 50s), kStale));
  EXPECT_FALSE(isHolderAlive(remote, formatUtc(now - 70s), kStale));
  EXPECT_FALSE(isHolderAlive(remote, "garbage", kStale));
}

TEST(Leases, LiveHolderBlocksASecondClaimer) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  Leases leases(db);
  const LeaseHolder me = currentProcessHolder(0);
  const LeaseHolder other = deadHolder();

  const auto first = leases.claim("k", me, kStale);
  EXPECT_TRUE(first.claimed);
  EXPECT_FALSE(first.liveHolder.has_value());

  const auto second = leases.claim("k", other, kStale);
  EXPECT_FALSE(second.claimed);
  ASSERT_TRUE(second.liveHolder.has_value());
  EXPECT_EQ(*second.liveHolder, me);
  EXPECT_EQ(*leases.holder("k"), me);

  // Claiming again what we hold succeeds (it only refreshes the heartbeat).
  EXPECT_TRUE(leases.claim("k", me, kStale).claimed);
}

TEST(Leases, DeadHoldersLeaseIsTakenOver) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  Leases leases(db);
  const LeaseHolder dead = deadHolder();
  ASSERT_TRUE(leases.claim("k", dead, kStale).claimed);  // as a crashed run would have left it
  LeaseHolder wrongStart = currentProcessHolder(0);
  wrongStart.pidStart = "1";
  ASSERT_TRUE(leases.claim("k2", wrongStart, kStale).claimed);

  const auto dead1 = leases.deadLeases(kStale);
  ASSERT_EQ(dead1.size(), 2u);
  EXPECT_EQ(dead1[0].first, "k");
  EXPECT_EQ(dead1[0].second, dead);

  const LeaseHolder me = currentProcessHolder(0);
  EXPECT_TRUE(leases.claim("k", me, kStale).claimed);
  EXPECT_TRUE(leases.claim("k2", me, kStale).claimed);
  EXPECT_EQ(*leases.holder("k"), me);
  EXPECT_TRUE(leases.deadLeases(kStale).empty());

  // The dead holder's late heartbeat or release must not touch the new holder's lease.
  setHeartbeat(db, "k", "2000-01-01T00:00:00.000Z");
  leases.heartbeat("k", dead);
  leases.release("k", dead);
  EXPECT_EQ(heartbeatOf(db, "k"), "2000-01-01T00:00:00.000Z");
  EXPECT_EQ(*leases.holder("k"), me);
}

TEST(Leases, OtherHostLeaseIsTakenOverOnlyWhenItsHeartbeatIsStale) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  Leases leases(db);
  const LeaseHolder remote{"elsewhere.invalid", 1, "12345", 0};
  ASSERT_TRUE(leases.claim("k", remote, kStale).claimed);
  const LeaseHolder me = currentProcessHolder(0);
  EXPECT_FALSE(leases.claim("k", me, kStale).claimed);
  EXPECT_TRUE(leases.deadLeases(kStale).empty());

  setHeartbeat(db, "k", formatUtc(std::chrono::system_clock::now() - 2 * kStale));
  ASSERT_EQ(leases.deadLeases(kStale).size(), 1u);
  EXPECT_TRUE(leases.claim("k", me, kStale).claimed);
  EXPECT_EQ(*leases.holder("k"), me);
}

TEST(Leases, HeartbeatSetRunAndReleaseAffectOnlyTheHoldersLease) {
  TempDir dir;
  Database db = Database::open(dir / "gb.sqlite");
  Leases leases(db);
  const LeaseHolder me = currentProcessHolder(0);
  const LeaseHolder stranger{"elsewhere.invalid", 1, "12345", 0};
  ASSERT_TRUE(leases.claim("k", me, kStale).claimed);
  setHeartbeat(db, "k", "2000-01-01T00:00:00.000Z");
  leases.heartbeat("k", stranger);
  EXPECT_EQ(heartbeatOf(db, "k"), "2000-01-01T00:00:00.000Z");
  leases.heartbeat("k", me);
  EXPECT_GT(heartbeatOf(db, "k"), "2000-01-01T00:00:00.000Z");

  EXPECT_FALSE(leases.setRun("k", stranger, 5));
  leases.release("k", stranger);
  EXPECT_TRUE(leases.holder("k").has_value());
  leases.release("k", me);
  EXPECT_FALSE(leases.holder("k").has_value());
  EXPECT_TRUE(leases.claim("k", stranger, kStale).claimed);  // free again
}

TEST(Heartbeat, BackgroundThreadAdvancesHeartbeat) {
  TempDir dir;
  const auto path = dir / "gb.sqlite";
  Database db = Database::open(path);
  Leases leases(db);
  const LeaseHolder me = currentProcessHolder(0);
  ASSERT_TRUE(leases.claim("a", me, kStale).claimed);
  ASSERT_TRUE(leases.claim("b", me, kStale).claimed);
  const std::string old = "2000-01-01T00:00:00.000Z";
  setHeartbeat(db, "a", old);
  setHeartbeat(db, "b", old);
  {
    Heartbeat heartbeat(path, me, 50ms);
    heartbeat.add("a");
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (heartbeatOf(db, "a") == old && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(10ms);
    EXPECT_GT(heartbeatOf(db, "a"), old);
    EXPECT_GE(heartbeat.beats(), 1u);
    heartbeat.remove("a");
  }                                      // joins
  EXPECT_EQ(heartbeatOf(db, "b"), old);  // never added
}

TEST(Heartbeat, SkipsBeatsWhileTheDatabaseIsLockedAndRecovers) {
  TempDir dir;
  const auto path = dir / "gb.sqlite";
  Database db = Database::open(path);
  const LeaseHolder me = currentProcessHolder(0);
  ASSERT_TRUE(Leases(db).claim("a", me, kStale).claimed);
  const std::string old = "2000-01-01T00:00:00.000Z";
  setHeartbeat(db, "a", old);

  Heartbeat heartbeat(path, me, 50ms);
  heartbeat.add("a");
  db.exec("BEGIN IMMEDIATE");
  std::this_thread::sleep_for(400ms);
  EXPECT_EQ(heartbeat.beats(), 0u);
  db.exec("COMMIT");
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (heartbeatOf(db, "a") == old && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(10ms);
  EXPECT_GT(heartbeatOf(db, "a"), old);
}

}  // namespace
}  // namespace grainbridge::db
