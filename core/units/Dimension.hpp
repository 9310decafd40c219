#pragma once
// Physical dimension of a parameter as exponents of length, mass and time. Declared once per
// parameter; from it follow the SI unit a quantity string must convert to and the scale of a
// reduced-unit number (d0^L m0^M t0^T, Table 6.1's reduced units).
#include <string>

namespace grainbridge::core::units {

struct Dimension {
  int length = 0;
  int mass = 0;
  int time = 0;

  static constexpr Dimension none() { return {0, 0, 0}; }
  static constexpr Dimension lengthDim() { return {1, 0, 0}; }
  static constexpr Dimension massDim() { return {0, 1, 0}; }
  static constexpr Dimension timeDim() { return {0, 0, 1}; }
  static constexpr Dimension velocity() { return {1, 0, -1}; }
  static constexpr Dimension acceleration() { return {1, 0, -2}; }
  static constexpr Dimension frequency() { return {0, 0, -1}; }
  static constexpr Dimension density() { return {-3, 1, 0}; }
  static constexpr Dimension force() { return {1, 1, -2}; }
  static constexpr Dimension stiffness() { return {0, 1, -2}; }            // N/m
  static constexpr Dimension pressure() { return {-1, 1, -2}; }            // Pa
  static constexpr Dimension viscosity() { return {-1, 1, -1}; }           // Pa s
  static constexpr Dimension granularTemperature() { return {2, 0, -2}; }  // m^2/s^2

  [[nodiscard]] bool isNone() const { return length == 0 && mass == 0 && time == 0; }
  // The SI unit in udunits2 syntax ("m s-1", "kg m-3", "1" for dimensionless).
  [[nodiscard]] std::string siUnit() const;
  friend bool operator==(const Dimension&, const Dimension&) = default;
};

}  // namespace grainbridge::core::units
