#pragma once
// The drag law of a resolved mfm or tfdem stage config: the law `drag` names with the values of
// its stage keys (DragSchema.hpp declares them). Kept apart from DragSchema.hpp so a stage's
// set-up code sees engines/closures only.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>

#include "engines/closures/GasSolidsDrag.hpp"

namespace grainbridge::workflows::stages {

// The law resolved params `p` choose, with its stage keys' values. A parameter set the law's check
// refuses (Eq. 3.14) is reported by `problem` at the pointer of the key to change ("/drag_d").
template <class Laws = grainbridge::closures::DragLaws>
grainbridge::closures::GasSolidsDragOf<Laws> dragFromParams(
    const nlohmann::json& p, const std::function<void(const std::string&, const std::string&)>& problem) {
  auto drag = grainbridge::closures::GasSolidsDragOf<Laws>::byName(p.at("drag").get<std::string>());
  std::visit(
      [&]<class Law>(Law& law) {
        for (const auto& parameter : Law::parameters) {
          if (parameter.stageKey == nullptr) continue;
          law.params.*parameter.member = p.at(parameter.stageKey).template get<double>();
        }
        const auto found = grainbridge::closures::paramsProblem<Law>(law.params);
        if (found.why.empty()) return;
        std::string pointer = "/drag";  // a parameter no stage key sets: the law's choice is at fault
        for (const auto& parameter : Law::parameters) {
          if (parameter.stageKey != nullptr && found.key == parameter.key)
            pointer = std::string("/") + parameter.stageKey;
        }
        problem(pointer, found.why);
      },
      drag.law);
  return drag;
}

}  // namespace grainbridge::workflows::stages
