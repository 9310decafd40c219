#pragma once
// A reason an engine cannot run its setup, found before the first step: the JSON pointer of the
// setup key at fault ("/box_hi/0", "/boundaries/2/to") and a message that names the value and the
// fix. An engine's typed setup struct lists them in problems(); the engine refuses to start on
// any, and a stage reports each at config load under its own params pointer, so every rule is
// written once (docs/engine-stages.md, section 2).
#include <string>

namespace grainbridge::core::engine {

struct SetupProblem {
  std::string pointer;
  std::string message;
};

}  // namespace grainbridge::core::engine
