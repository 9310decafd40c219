#include "engines/dem/Walls.hpp"

#include "core/Error.hpp"

namespace grainbridge::dem {

const char* vibrationStartName(Vibration::Start start) {
  return start == Vibration::Start::AtRest ? "at_rest" : "mid_stroke";
}

Vibration::Start vibrationStartFromName(const std::string& name) {
  if (name == "mid_stroke") return Vibration::Start::MidStroke;
  if (name == "at_rest") return Vibration::Start::AtRest;
  throw Error("vibration_start: \"" + name + "\" is neither \"mid_stroke\" nor \"at_rest\"");
}

}  // namespace grainbridge::dem
