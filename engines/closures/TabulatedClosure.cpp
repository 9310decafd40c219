#include "engines/closures/TabulatedClosure.hpp"

#include <cmath>
#include <sstream>

#include "core/ClosureForms.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"

namespace grainbridge::closures {

std::string_view toString(OutOfRangePolicy policy) {
  switch (policy) {
    case OutOfRangePolicy::Error:
      return "error";
    case OutOfRangePolicy::Clamp:
      return "clamp";
    case OutOfRangePolicy::KineticTheory:
      return "kinetic_theory";
  }
  return "?";
}

OutOfRangePolicy outOfRangePolicyFromString(std::string_view name) {
  for (auto p : {OutOfRangePolicy::Error, OutOfRangePolicy::Clamp, OutOfRangePolicy::KineticTheory}) {
    if (toString(p) == name) return p;
  }
  throw Error("unknown out-of-range policy \"" + std::string(name) + "\" (expected error, clamp or kinetic_theory)");
}

TabulatedClosure::TabulatedClosure(core::ClosureTable table, OutOfRangePolicy policy, KineticModelName fallback)
    : table_(std::move(table)), policy_(policy), fallback_(fallback) {
  const std::string& q = table_.quantity();
  if (q == "p_theta") {
    quantity_ = Quantity::Pressure;
  } else if (q == "eta_theta") {
    quantity_ = Quantity::Viscosity;
  } else if (q == "j_theta") {
    quantity_ = Quantity::Dissipation;
  } else {
    throw Error("closure table of \"" + q +
                "\": a continuum engine can use p_theta, eta_theta or j_theta (the theta-scaled forms)");
  }
  if (table_.threeDimensional()) {
    throw Error("closure table " + q + ": a table of three axes (" + table_.secondVariable() + ", " +
                table_.thirdVariable() + ") is a mixture species' (issue 60); a continuum phase's table has solid "
                "fraction and restitution");
  }
  if (table_.twoDimensional() && table_.secondVariable() != "restitution") {
    throw Error("closure table " + q + ": second variable \"" + table_.secondVariable() +
                "\" is not a kinetic-theory state variable (expected restitution)");
  }
}

TabulatedClosure::TabulatedClosure(const TabulatedClosure& other)
    : table_(other.table_),
      policy_(other.policy_),
      fallback_(other.fallback_),
      quantity_(other.quantity_),
      outOfRange_(other.outOfRangeCount()) {}

TabulatedClosure& TabulatedClosure::operator=(const TabulatedClosure& other) {
  if (this == &other) return *this;
  table_ = other.table_;
  policy_ = other.policy_;
  fallback_ = other.fallback_;
  quantity_ = other.quantity_;
  outOfRange_.store(other.outOfRangeCount(), std::memory_order_relaxed);
  return *this;
}

ClosureValue TabulatedClosure::evaluate(const KineticState& state) const {
  validate(state);
  const auto lookup = table_(state.solidFraction, state.restitution);
  ClosureValue out;
  if (!lookup.inRange) {
    const auto count = outOfRange_.fetch_add(1, std::memory_order_relaxed);
    std::ostringstream where;
    where << "solid fraction " << state.solidFraction;
    if (table_.twoDimensional()) where << ", restitution " << state.restitution;
    where << " is outside the " << table_.quantity() << " table (solid fraction " << table_.solidFractions().front()
          << " to " << table_.solidFractions().back();
    if (table_.twoDimensional()) {
      where << ", restitution " << table_.seconds().front() << " to " << table_.seconds().back();
    }
    where << ")";
    switch (policy_) {
      case OutOfRangePolicy::Error:
        throw Error(where.str() + "; out-of-range policy is error");
      case OutOfRangePolicy::Clamp:
        out.source = ClosureValue::Source::TableEdge;
        break;
      case OutOfRangePolicy::KineticTheory: {
        // One warning per closure: a continuum engine evaluates this per cell and step.
        if (count == 0) {
          spdlog::warn("{}; using {} there (further cases are counted, not logged)", where.str(), toString(fallback_));
        }
        const auto kt = closures::evaluate(fallback_, state);
        out.source = ClosureValue::Source::KineticTheory;
        out.value = quantity_ == Quantity::Pressure    ? kt.pressure
                    : quantity_ == Quantity::Viscosity ? kt.shearViscosity
                                                       : kt.dissipationRate;
        return out;
      }
    }
  }
  const core::ClosureForm form = quantity_ == Quantity::Pressure    ? core::ClosureForm::PTheta
                                 : quantity_ == Quantity::Viscosity ? core::ClosureForm::EtaTheta
                                                                    : core::ClosureForm::JTheta;
  out.value = core::fromClosureForm(form, lookup.value, {state.density, state.diameter, state.granularTemperature});
  return out;
}

}  // namespace grainbridge::closures
