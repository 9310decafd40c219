#pragma once
// The unit system a config's bare numbers are in. SI, or the dissertation's reduced units
// (Table 6.1): length d0, mass m0, time t0 = sqrt(d0/g). Engines work in SI; a config in reduced
// units is converted once, at load, by toSI().
#include <nlohmann/json.hpp>

#include "core/units/Dimension.hpp"

namespace grainbridge::core::units {

class UnitSystem {
 public:
  static UnitSystem si() { return UnitSystem(); }
  // d0 [m], m0 [kg], g [m/s^2]; all must be positive.
  static UnitSystem reduced(double d0, double m0, double g);

  [[nodiscard]] bool isReduced() const { return reduced_; }
  // Converts a bare number given in this system to SI.
  [[nodiscard]] double toSI(double value, const Dimension& dim) const;
  [[nodiscard]] double d0() const { return d0_; }
  [[nodiscard]] double m0() const { return m0_; }
  [[nodiscard]] double t0() const { return t0_; }
  [[nodiscard]] nlohmann::json toJson() const;
  // Inverse of toJson (used to hand a stage's unit system to an MPI worker).
  static UnitSystem fromJson(const nlohmann::json& j);

 private:
  bool reduced_ = false;
  double d0_ = 1.0;
  double m0_ = 1.0;
  double t0_ = 1.0;
};

}  // namespace grainbridge::core::units
