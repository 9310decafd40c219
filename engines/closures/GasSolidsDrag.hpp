#pragma once
// The gas-solids drag laws, selected by name: syamlal_obrien (Eqs. 3.10-3.16, the multi-fluid
// default as the reference ran MFIX), ergun_wen_yu (Eqs. 7.30-7.31 as printed, the TF-DEM
// default) and gidaspow (Gidaspow's published form of the same law). The law is a
// std::variant, so an engine visits it once per sweep over its cells or particles and the loop
// inside inlines the law (STYLE.md 3).
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "engines/closures/ErgunWenYu.hpp"
#include "engines/closures/SyamlalOBrien.hpp"

namespace grainbridge::closures {

using DragLaw = std::variant<SyamlalOBrien, ErgunWenYu>;

struct GasSolidsDrag {
  std::string name;
  DragLaw law;

  [[nodiscard]] DragCoefficients evaluate(const DragState& state) const {
    return std::visit([&state](const auto& l) { return l.evaluate(state); }, law);
  }
  // Every name byName() accepts.
  [[nodiscard]] static std::vector<std::string> names();
  // The law of that name with its default parameters; throws grainbridge::Error naming the
  // known names otherwise.
  [[nodiscard]] static GasSolidsDrag byName(std::string_view name);
};

}  // namespace grainbridge::closures
