#pragma once
// The gas-solids drag law a continuum engine's set-up reads (mfm, tfdem): the law the `drag` key
// names, its parameters from the keys the law declares (DragLawTraits.hpp, `stageKey`), and the
// law's own check of them (Eq. 3.14) as a set-up problem at the pointer of the key to change.
// Reading and checking are apart so a set-up's from_json reads and its problems() checks.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>

#include "core/engine/SetupProblem.hpp"
#include "engines/closures/GasSolidsDrag.hpp"

namespace grainbridge::closures {

// The law `p`'s "drag" names with the values of its keys; assumes the keys were checked against
// their schema (present, in range).
template <class Laws = DragLaws>
[[nodiscard]] GasSolidsDragOf<Laws> dragFromJson(const nlohmann::json& p) {
  auto drag = GasSolidsDragOf<Laws>::byName(p.at("drag").get<std::string>());
  std::visit(
      [&]<class Law>(Law& law) {
        for (const auto& parameter : Law::parameters) {
          if (parameter.stageKey == nullptr) continue;
          law.params.*parameter.member = p.at(parameter.stageKey).template get<double>();
        }
      },
      drag.law);
  return drag;
}

// Why the law cannot use its parameters, at the pointer of the key to change ("/drag_d"; "/drag"
// when no key sets the parameter at fault: then the law's choice is).
template <class Laws = DragLaws>
[[nodiscard]] std::optional<core::engine::SetupProblem> dragProblem(const GasSolidsDragOf<Laws>& drag) {
  return std::visit(
      [&]<class Law>(const Law& law) -> std::optional<core::engine::SetupProblem> {
        const auto found = paramsProblem<Law>(law.params);
        if (found.why.empty()) return std::nullopt;
        std::string pointer = "/drag";
        for (const auto& parameter : Law::parameters) {
          if (parameter.stageKey != nullptr && found.key == parameter.key)
            pointer = std::string("/") + parameter.stageKey;
        }
        return core::engine::SetupProblem{pointer, found.why};
      },
      drag.law);
}

}  // namespace grainbridge::closures
