#pragma once
// The solids closure a continuum engine calls (DESIGN.md "Closures"): one call,
// evaluate(state) -> KineticTransport, whichever the config chose:
//   ktgf   a kinetic-theory model of engines/closures (lun1984 the default);
//   table  DEM closure tables (TabulatedClosure, with their out-of-range policy) for the
//          quantities they hold - solids pressure, shear viscosity, collisional dissipation -
//          and the named kinetic-theory model for the rest (conductivity, bulk viscosity),
//          which no table holds.
// The choice is made once, when the model is built; the engine's loop calls evaluate() the same
// way for both and never branches on which.
#include <optional>
#include <string_view>

#include "engines/closures/KineticModel.hpp"
#include "engines/closures/TabulatedClosure.hpp"

namespace grainbridge::closures {

class ClosureModel {
 public:
  // Every quantity from `model`.
  [[nodiscard]] static ClosureModel kineticTheory(KineticModelName model = kDefaultKineticModel);
  // The quantities a table is given for from that table, the rest from `model`. At least one
  // table; each must hold the quantity of its slot (p_theta, eta_theta, j_theta), or
  // grainbridge::Error says which.
  [[nodiscard]] static ClosureModel tabulated(KineticModelName model, std::optional<TabulatedClosure> pressure,
                                              std::optional<TabulatedClosure> shearViscosity,
                                              std::optional<TabulatedClosure> dissipation);

  // "ktgf" or "table".
  [[nodiscard]] std::string_view kind() const { return tabulated_ ? "table" : "ktgf"; }
  [[nodiscard]] KineticModelName kineticModel() const { return model_; }
  // Throws grainbridge::Error for a state the model refuses (validate(KineticState)) or, under
  // the error policy, outside a table.
  [[nodiscard]] KineticTransport evaluate(const KineticState& state) const;
  // The kinetic model's own pressure at `state`, given `evaluated` = evaluate(state): that
  // value itself when no table supplies the pressure, so a caller that needs the model's
  // pressure beside the closure's (the solids-pressure slope) evaluates the model once per cell
  // without asking which kind of closure it holds.
  [[nodiscard]] double modelPressure(const KineticState& state, const KineticTransport& evaluated) const;
  // Evaluations that fell outside a table, over every table of the model.
  [[nodiscard]] std::int64_t outOfRangeCount() const;
  // Whether every table of the model holds `state` (its solid fraction and restitution inside
  // the table's axes); true for `ktgf`. What a continuum run's coverage counts, without
  // evaluating or counting anything.
  [[nodiscard]] bool covers(const KineticState& state) const;

 private:
  explicit ClosureModel(KineticModelName model) : model_(model) {}

  KineticModelName model_;
  bool tabulated_ = false;
  std::optional<TabulatedClosure> pressure_, shearViscosity_, dissipation_;
};

}  // namespace grainbridge::closures
