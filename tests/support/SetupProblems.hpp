#pragma once
// The JSON pointers of an engine set-up's problems (core/engine/SetupProblem), in order: what the
// problems() tests of every engine compare.
#include <string>
#include <vector>

#include "core/engine/SetupProblem.hpp"

namespace grainbridge::testing {

inline std::vector<std::string> pointersOf(const std::vector<core::engine::SetupProblem>& problems) {
  std::vector<std::string> out;
  for (const auto& p : problems) out.push_back(p.pointer);
  return out;
}

}  // namespace grainbridge::testing
