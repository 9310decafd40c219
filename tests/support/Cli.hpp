#pragma once
// Helpers for tests that drive the grainbridge binary the way a user does: run a command line,
// capture its output and exit status, work in a fresh temporary folder.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "tests/support/TempDir.hpp"

namespace grainbridge::testing {

struct CommandResult {
  int exitCode = -1;   // exit status, or 128 + signal number if killed by a signal
  std::string output;  // stdout and stderr interleaved
};

inline CommandResult runCommand(const std::string& command) {
  CommandResult r;
  FILE* p = ::popen((command + " 2>&1").c_str(), "r");
  if (p == nullptr) return r;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
  const int status = ::pclose(p);
  // popen runs /bin/sh -c, which reports a child killed by signal s as exit 128 + s.
  if (WIFEXITED(status))
    r.exitCode = WEXITSTATUS(status);
  else if (WIFSIGNALED(status))
    r.exitCode = 128 + WTERMSIG(status);
  return r;
}

inline std::string grainbridgeBinary() { return GRAINBRIDGE_BINARY; }
inline std::filesystem::path sourceDir() { return GRAINBRIDGE_SOURCE_DIR; }

inline void writeText(const std::filesystem::path& p, const std::string& text) {
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

inline std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Waits (up to `timeoutMs`) until process `pid` has exited. A zombie counts as exited: a
// background process whose shell is gone may never be reaped in a container.
inline void waitForProcessExit(long pid, int timeoutMs = 240000) {
  const std::filesystem::path stat = "/proc/" + std::to_string(pid) + "/stat";
  for (int waited = 0; waited < timeoutMs; waited += 20) {
    std::ifstream in(stat);
    std::string text;
    if (!in || !std::getline(in, text)) return;
    const auto close = text.rfind(')');
    if (close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'Z') return;
    ::usleep(20000);
  }
}

// Runs `grainbridge <args>` with `workdir` as the current folder.
inline CommandResult runGrainbridge(const std::filesystem::path& workdir, const std::string& args,
                                    const std::string& env = "") {
  return runCommand("cd '" + workdir.string() + "' && " + env + (env.empty() ? "" : " ") + grainbridgeBinary() + " " +
                    args);
}

}  // namespace grainbridge::testing
