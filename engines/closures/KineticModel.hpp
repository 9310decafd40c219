#pragma once
// Choosing a kinetic-theory model by name (config value, compare stage). A closed enum and a
// switch instead of a virtual hierarchy: the models are small value types (STYLE.md 3) and the
// set is fixed at compile time. Adding a model means a new enumerator, a name in
// KineticModel.cpp and a case in evaluate().
#include <array>
#include <string_view>

#include "engines/closures/KineticState.hpp"

namespace grainbridge::closures {

enum class KineticModelName {
  Lun1984,                  // "lun1984": Lun et al. 1984 + Ma-Ahmadi (Lun1984.hpp), the default
  Lun1984Mfix,              // "lun1984_mfix": the same with MFIX's shear viscosity factor 1.2
  SyamlalAlgebraicPrinted,  // "syamlal_algebraic": Eqs. 3.21-3.25 as printed (SyamlalAlgebraic.hpp)
  SyamlalAlgebraicMfix,     // "syamlal_algebraic_mfix": Eq. 3.25 with MFIX's (3e + 1)/2
};

// What the reference's Chapter 5 ran and what DEM is compared against (DESIGN.md, VALIDATION.md).
inline constexpr KineticModelName kDefaultKineticModel = KineticModelName::Lun1984;

// Every model, in enum order, for tests and listings that must cover all of them.
inline constexpr std::array<KineticModelName, 4> kAllKineticModels = {
    KineticModelName::Lun1984, KineticModelName::Lun1984Mfix, KineticModelName::SyamlalAlgebraicPrinted,
    KineticModelName::SyamlalAlgebraicMfix};

// The config name: "lun1984", "lun1984_mfix", "syamlal_algebraic" or "syamlal_algebraic_mfix".
[[nodiscard]] std::string_view toString(KineticModelName model);

// Exact, case-sensitive match of toString(); anything else throws grainbridge::Error naming the
// value given and listing the valid names.
[[nodiscard]] KineticModelName kineticModelFromString(std::string_view name);

// Validates the state and evaluates the chosen model.
[[nodiscard]] KineticTransport evaluate(KineticModelName model, const KineticState& state);

}  // namespace grainbridge::closures
