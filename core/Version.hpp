#pragma once
// The build's code version, embedded at build time (cmake/WriteBuildVersion.cmake). It is
// provenance only: recorded in every artifact and run, never part of a stage key.
#include <string>

namespace grainbridge::core {
struct CodeVersion {
  std::string release;  // project version from CMakeLists.txt
  std::string gitSha;   // "unknown" outside a git checkout
  bool dirty;           // tracked files differed from gitSha when built
  [[nodiscard]] std::string describe() const { return gitSha + (dirty ? "-dirty" : ""); }
};
const CodeVersion& codeVersion();
}  // namespace grainbridge::core
