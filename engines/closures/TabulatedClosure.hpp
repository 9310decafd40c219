#pragma once
// A DEM-tabulated closure used the way a continuum engine needs it: with the engine's local
// granular temperature. Tables hold the theta-scaled dimensionless forms of DESIGN.md
// ("Closures") against solid fraction [and restitution]:
//   p_theta   = p  / (rho_p theta)              -> solids pressure
//   eta_theta = mu / (rho_p d sqrt(theta))      -> shear viscosity
//   j_theta   = J d / (rho_p theta^(3/2))       -> collisional dissipation rate
// so the SI value at a state is the table value times the scale of that state. Outside the
// table the out-of-range policy decides: stop with an error, use the value at the table's
// edge, or fall back to a kinetic-theory model (logged once per closure, counted always).
#include <atomic>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/ClosureTable.hpp"
#include "engines/closures/KineticModel.hpp"
#include "engines/closures/KineticState.hpp"

namespace grainbridge::closures {

enum class OutOfRangePolicy {
  Error,          // "error": a state outside the table is a mistake in the setup
  Clamp,          // "clamp": the value at the nearest edge of the table
  KineticTheory,  // "kinetic_theory": the fallback model's value, with a logged warning
};

[[nodiscard]] std::string_view toString(OutOfRangePolicy policy);
// Throws grainbridge::Error naming the value and listing the valid names.
[[nodiscard]] OutOfRangePolicy outOfRangePolicyFromString(std::string_view name);

struct ClosureValue {
  enum class Source { Table, TableEdge, KineticTheory };
  double value = 0.0;  // SI
  Source source = Source::Table;
};

class TabulatedClosure {
 public:
  // `table.quantity()` must be p_theta, eta_theta or j_theta, and its second variable (if
  // any) restitution; otherwise grainbridge::Error says what is supported.
  TabulatedClosure(core::ClosureTable table, OutOfRangePolicy policy, KineticModelName fallback = kDefaultKineticModel);
  TabulatedClosure(const TabulatedClosure& other);
  TabulatedClosure& operator=(const TabulatedClosure& other);

  [[nodiscard]] ClosureValue evaluate(const KineticState& state) const;

  [[nodiscard]] const core::ClosureTable& table() const { return table_; }
  [[nodiscard]] OutOfRangePolicy policy() const { return policy_; }
  // How many evaluations so far fell outside the table (whatever the policy did about it).
  [[nodiscard]] std::int64_t outOfRangeCount() const { return outOfRange_.load(std::memory_order_relaxed); }

 private:
  enum class Quantity { Pressure, Viscosity, Dissipation };

  core::ClosureTable table_;
  OutOfRangePolicy policy_;
  KineticModelName fallback_;
  Quantity quantity_;
  mutable std::atomic<std::int64_t> outOfRange_{0};
};

}  // namespace grainbridge::closures
