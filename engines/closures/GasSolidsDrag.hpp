#pragma once
// The gas-solids drag laws, selected by name: syamlal_obrien (Eqs. 3.10-3.16, the multi-fluid
// default as the reference ran MFIX), ergun_wen_yu (Eqs. 7.30-7.31 as printed, the TF-DEM
// default) and gidaspow (Gidaspow's published form of the same law). Adding a law is one struct
// (beside these, declaring what DragLawTraits.hpp lists) plus one line in DragLaws below; the
// engines, the closure catalog, the mfm and tfdem stages' `drag` option and the generic drag
// tests read the list (docs/adding-a-drag-law.md).
//
// The law is a std::variant of the list, so an engine visits it once per sweep over its cells or
// particles (visit()) and the loop inside calls the chosen law directly (STYLE.md 3).
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "engines/closures/ErgunWenYu.hpp"
#include "engines/closures/SyamlalOBrien.hpp"

namespace grainbridge::closures {

template <class... L>
struct TypeList {};

// ---- the registry: one line per drag law --------------------------------------------------------
using DragLaws = TypeList<SyamlalOBrien,        //
                          ErgunWenYuAsPrinted,  //
                          Gidaspow>;
// ------------------------------------------------------------------------------------------------

// A list with more laws after those of `List` (a test's own law beside the registered ones).
template <class List, class... More>
struct AppendDragLaws;
template <class... L, class... More>
struct AppendDragLaws<TypeList<L...>, More...> {
  using type = TypeList<L..., More...>;
};

template <class... L>
constexpr bool distinctNames() {
  const std::array<std::string_view, sizeof...(L)> n{L::name...};
  for (std::size_t i = 0; i < n.size(); ++i) {
    for (std::size_t j = i + 1; j < n.size(); ++j) {
      if (n[i] == n[j]) return false;
    }
  }
  return true;
}

// Names the known names; byName's error.
[[noreturn]] void throwUnknownDragLaw(std::string_view name, const std::vector<std::string>& known);

// A law of `Laws` chosen by name. Everything that chooses a law reads it through this template,
// so a list with one more law (AppendDragLaws) is accepted everywhere the registry is.
template <class Laws>
struct GasSolidsDragOf;

template <class... L>
struct GasSolidsDragOf<TypeList<L...>> {
  using Law = std::variant<L...>;
  std::string name;
  Law law;

  // One state: visits the variant for this call. A sweep calls visit() once instead.
  [[nodiscard]] DragCoefficients evaluate(const DragState& state) const {
    return std::visit([&state](const auto& l) { return l.evaluate(state); }, law);
  }
  // f(const ChosenLaw&): the caller's loop, instantiated for each law of the list.
  template <class F>
  decltype(auto) visit(F&& f) const {
    return std::visit(std::forward<F>(f), law);
  }
  // Every name byName() accepts, in the list's order.
  [[nodiscard]] static std::vector<std::string> names() { return {L::name...}; }
  // The law of that name with its default parameters; throws grainbridge::Error naming the
  // known names otherwise.
  [[nodiscard]] static GasSolidsDragOf byName(std::string_view name) {
    std::optional<GasSolidsDragOf> found;
    ((found || name != L::name ? void() : void(found = GasSolidsDragOf{std::string(name), Law(std::in_place_type<L>)})),
     ...);
    if (!found) throwUnknownDragLaw(name, names());
    return *found;
  }

  static_assert(distinctNames<L...>(), "two drag laws of one list share a name: byName could not tell them apart");
};

using GasSolidsDrag = GasSolidsDragOf<DragLaws>;
using DragLaw = GasSolidsDrag::Law;

}  // namespace grainbridge::closures
