#pragma once
// The absolute path of a member of a group inside an HDF5 file: "/" + name in the root,
// "<group>/<name>" elsewhere. A writer that takes its group as a parameter (a checkpoint's
// engine state, the root for a single engine, its own group in a coupled engine's file) builds
// every dataset and attribute path with it, so "/" and "/dem" need no special case at the
// call site.
#include <string>

namespace grainbridge::core::io {

[[nodiscard]] inline std::string memberPath(const std::string& group, const std::string& name) {
  if (group.empty() || group == "/") return "/" + name;
  return group.back() == '/' ? group + name : group + "/" + name;
}

}  // namespace grainbridge::core::io
