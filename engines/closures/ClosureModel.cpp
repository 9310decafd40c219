#include "engines/closures/ClosureModel.hpp"

#include "core/Error.hpp"

namespace grainbridge::closures {

ClosureModel ClosureModel::kineticTheory(KineticModelName model) { return ClosureModel(model); }

ClosureModel ClosureModel::tabulated(KineticModelName model, std::optional<TabulatedClosure> pressure,
                                     std::optional<TabulatedClosure> shearViscosity,
                                     std::optional<TabulatedClosure> dissipation) {
  if (!pressure && !shearViscosity && !dissipation) {
    throw Error("closure model \"table\": no table given (pressure, shear viscosity or dissipation)");
  }
  auto expect = [](const std::optional<TabulatedClosure>& t, const char* quantity, const char* slot) {
    if (t && t->table().quantity() != quantity) {
      throw Error(std::string("closure model \"table\": the ") + slot + " table holds " + t->table().quantity() +
                  ", not " + quantity);
    }
  };
  expect(pressure, "p_theta", "solids pressure");
  expect(shearViscosity, "eta_theta", "shear viscosity");
  expect(dissipation, "j_theta", "dissipation");
  ClosureModel m(model);
  m.tabulated_ = true;
  // emplace: a TabulatedClosure copies (its out-of-range counter is atomic) but does not assign.
  if (pressure) m.pressure_.emplace(*pressure);
  if (shearViscosity) m.shearViscosity_.emplace(*shearViscosity);
  if (dissipation) m.dissipation_.emplace(*dissipation);
  return m;
}

double ClosureModel::modelPressure(const KineticState& state, const KineticTransport& evaluated) const {
  return pressure_ ? closures::evaluate(model_, state).pressure : evaluated.pressure;
}

KineticTransport ClosureModel::evaluate(const KineticState& state) const {
  KineticTransport t = closures::evaluate(model_, state);
  if (pressure_) t.pressure = pressure_->evaluate(state).value;
  if (shearViscosity_) {
    // Keep the model's true bulk viscosity xi: only mu comes from the table.
    t.shearViscosity = shearViscosity_->evaluate(state).value;
  }
  if (dissipation_) t.dissipationRate = dissipation_->evaluate(state).value;
  return t;
}

bool ClosureModel::covers(const KineticState& state) const {
  for (const auto* t : {&pressure_, &shearViscosity_, &dissipation_}) {
    if (*t && !(*t)->table()(state.solidFraction, state.restitution).inRange) return false;
  }
  return true;
}

std::int64_t ClosureModel::outOfRangeCount() const {
  std::int64_t n = 0;
  for (const auto* t : {&pressure_, &shearViscosity_, &dissipation_}) {
    if (*t) n += (*t)->outOfRangeCount();
  }
  return n;
}

}  // namespace grainbridge::closures
