#include "db/Heartbeat.hpp"

#include <algorithm>

#include "core/Log.hpp"
#include "db/BusyError.hpp"
#include "db/Leases.hpp"

namespace grainbridge::db {

Heartbeat::Heartbeat(const std::filesystem::path& dbPath, LeaseHolder me, std::chrono::milliseconds period)
    : db_(Database::open(dbPath)), me_(std::move(me)), period_(period) {
  GB_ASSERT(period_.count() > 0, "heartbeat period must be positive");
  // Waiting longer than a period for the lock is pointless (the next beat will try anyway)
  // and would delay the destructor; so is retrying BEGIN IMMEDIATE.
  db_.setBusyTimeout(std::clamp(period_, std::chrono::milliseconds(100), std::chrono::milliseconds(30000)));
  db_.setBusyRetries(0);
  thread_ = std::thread([this] { run(); });
}

Heartbeat::~Heartbeat() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void Heartbeat::add(const std::string& key) {
  std::lock_guard lock(mutex_);
  keys_.insert(key);
}

void Heartbeat::remove(const std::string& key) {
  std::lock_guard lock(mutex_);
  keys_.erase(key);
}

void Heartbeat::run() {
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, period_, [this] { return stop_; })) {
    const std::set<std::string> keys = keys_;
    // Beat without holding the mutex so add/remove never wait on the database.
    lock.unlock();
    beat(keys);
    lock.lock();
  }
}

void Heartbeat::beat(const std::set<std::string>& keys) {
  if (keys.empty()) return;
  try {
    db_.transaction([&](Database& db) {
      Leases leases(db);
      for (const std::string& key : keys) leases.heartbeat(key, me_);
    });
    ++beats_;
  } catch (const BusyError&) {
    // Another writer held the lock for a whole period; the next beat retries.
  } catch (const std::exception& e) {
    spdlog::warn("lease heartbeat for {}: {}", db_.path().string(), e.what());
  }
}

}  // namespace grainbridge::db
