#pragma once
// The gas-solids drag keys of the stages that run a drag law (mfm, tfdem): `drag`, whose options
// are the names of engines/closures' drag law list, and each law's stage keys (DragParameter's
// stageKey: drag_c and drag_d for syamlal_obrien's C and D), declared from the law's own
// parameter declarations as the closure catalog declares them; DragSetup.hpp reads them back.
// Templated on the list so a test can run a list with one more law through the same wiring
// (tests/workflows/DragLawWiringTest.cpp).
#include <string>

#include "engines/closures/GasSolidsDrag.hpp"
#include "workflows/closures/DragLawCatalog.hpp"
#include "workflows/params/ParamSchema.hpp"

namespace grainbridge::workflows::stages {

// Adds `drag` (default `defaultLaw`, which each stage chooses, and the stage's own `doc`) and
// then every stage key of every law, in the list's order.
template <class Laws = grainbridge::closures::DragLaws>
void addDragParams(params::ParamSchema& schema, const std::string& defaultLaw, const std::string& doc) {
  schema.add(params::ParamSpec::string("drag")
                 .defaultValue(defaultLaw)
                 .options(grainbridge::closures::GasSolidsDragOf<Laws>::names())
                 .doc(doc));
  [&schema]<class... L>(grainbridge::closures::TypeList<L...>) {
    auto addLaw = [&schema]<class Law>(const Law*) {
      for (const auto& p : Law::parameters) {
        if (p.stageKey != nullptr) schema.add(workflows::closures::dragParameterSpec<Law>(p).renamed(p.stageKey));
      }
    };
    (addLaw(static_cast<const L*>(nullptr)), ...);
  }(Laws{});
}

}  // namespace grainbridge::workflows::stages
