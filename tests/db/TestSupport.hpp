#pragma once
// Shared helpers for the db tests: a fresh temporary folder per test, sample records, and a
// process identity that is certainly dead (a reaped child).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <filesystem>
#include <random>
#include <string>

#include "db/Database.hpp"
#include "db/Leases.hpp"
#include "db/Records.hpp"

namespace grainbridge::db::test {

class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::random_device random;
    path_ = std::filesystem::temp_directory_path() /
            ("grainbridge-db-" + std::string(info != nullptr ? info->name() : "test") + "-" +
             std::to_string(::getpid()) + "-" + std::to_string(random()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline InvocationRecord sampleInvocation(const std::string& workflow = "shear") {
  InvocationRecord invocation;
  invocation.workflow = workflow;
  invocation.configPath = "configs/" + workflow + ".json";
  invocation.configJson = R"({"name":")" + workflow + R"("})";
  invocation.codeVersion = "0123abcd";
  invocation.codeDirty = true;
  invocation.host = "node01";
  invocation.pid = 4242;
  invocation.ranks = 2;
  invocation.startedAt = "2026-11-23T20:14:05.123Z";
  invocation.status = "running";
  return invocation;
}

inline RunRecord sampleRun(std::int64_t invocationId, const std::string& key, const std::string& workflow = "shear") {
  RunRecord run;
  run.invocationId = invocationId;
  run.workflow = workflow;
  run.stage = "bed";
  run.stageType = "dem";
  run.implVersion = 3;
  run.key = key;
  run.paramsJson = R"({"e":0.9})";
  run.instanceDir = "bed/" + key;
  run.codeVersion = "0123abcd";
  run.codeDirty = false;
  run.host = "node01";
  run.pid = 4242;
  run.rank = 1;
  run.ranks = 2;
  run.startedAt = "2026-11-23T20:14:06.000Z";
  run.status = "running";
  return run;
}

inline std::int64_t countRows(Database& db, const std::string& table) {
  Statement count = db.prepare("SELECT count(*) FROM " + table);
  count.step();
  return count.columnInt64(0);
}

// A holder identity of a process that really existed on this host (its true start time, read
// while it ran) and has exited and been reaped: the case a crashed run leaves behind.
inline LeaseHolder deadHolder() {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[1]);
    char c = 0;
    [[maybe_unused]] const auto n = ::read(fds[0], &c, 1);  // returns 0 once the parent closes
    ::_exit(0);
  }
  ::close(fds[0]);
  const std::optional<std::string> start = liveProcessStartTime(pid);
  ::close(fds[1]);
  ::waitpid(pid, nullptr, 0);
  if (!start) throw std::runtime_error("could not read the child's start time");
  return LeaseHolder{hostName(), pid, *start, 0};
}

}  // namespace grainbridge::db::test
