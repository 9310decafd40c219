#pragma once
// Keeps this process's leases fresh while its stages run, for the claimers on OTHER hosts that
// can only judge a holder by heartbeat age. A background thread with its own connection (a
// SQLite connection must not be shared between threads mid-statement, and the stage thread
// may be inside a long transaction) refreshes heartbeat_at of every key it was given, once per
// period. A busy database just skips a beat (the next one retries); other errors are logged,
// never thrown, because a missed heartbeat must not kill the stage it is protecting.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <set>
#include <string>
#include <thread>

#include "db/Database.hpp"
#include "db/Records.hpp"

namespace grainbridge::db {

class Heartbeat {
 public:
  // Opens its own connection to `dbPath` (throws Error if that fails) and starts the thread;
  // the first beat is one period after construction (claim() has just set the heartbeat).
  Heartbeat(const std::filesystem::path& dbPath, LeaseHolder me,
            std::chrono::milliseconds period = std::chrono::seconds(10));
  ~Heartbeat();  // stops and joins the thread
  Heartbeat(const Heartbeat&) = delete;
  Heartbeat& operator=(const Heartbeat&) = delete;

  void add(const std::string& key);
  void remove(const std::string& key);
  std::uint64_t beats() const { return beats_.load(); }  // successful beats so far (for tests)

 private:
  void run();
  void beat(const std::set<std::string>& keys);

  Database db_;
  LeaseHolder me_;
  std::chrono::milliseconds period_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::set<std::string> keys_;
  bool stop_ = false;
  std::atomic<std::uint64_t> beats_{0};
  std::thread thread_;  // last: starts only after every other member is constructed
};

}  // namespace grainbridge::db
