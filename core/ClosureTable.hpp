#pragma once
// A tabulated closure: one dimensionless transport coefficient (say p/(rho_p theta)) measured
// by DEM on a grid of solid fraction and, optionally, a second state variable (restitution).
// Pure data + interpolation, with no database and no policy: a lookup outside the table is
// clamped to its edge and flagged, and engines/closures decides what a flagged value means
// (error, clamp or kinetic-theory fallback; DESIGN.md "Closures").
//
// A mixture's species table (issue 60) has a third axis: (total solid fraction, the species'
// volume share x, restitution).
//
// Interpolation: monotone piecewise-cubic in solid fraction (Fritsch & Carlson 1980, the
// PCHIP slopes), because closures rise steeply towards random close packing and an ordinary
// cubic spline overshoots there, giving a pressure that falls as the bed compresses; linear
// in the second variable, which is sampled coarsely (four restitutions, say), and in the third
// (bilinear in the two together). The
// Fritsch-Carlson slopes are a dozen lines; Boost.Math or GSL have them too, but either would
// be a new dependency for that.
#include <string>
#include <vector>

namespace grainbridge::core {

struct ClosureLookup {
  double value = 0.0;
  // False when the state lay outside the table; value is then the table at the nearest edge.
  bool inRange = true;
};

class ClosureTable {
 public:
  // 1-D table: values at strictly increasing solid fractions.
  ClosureTable(std::string quantity, std::vector<double> solidFraction, std::vector<double> values);
  // 2-D table: values[iy * solidFraction.size() + ix] at (solidFraction[ix], second[iy]);
  // both axes strictly increasing. Throws grainbridge::Error naming the quantity and what is
  // wrong (size mismatch, an axis not increasing, a non-finite value).
  ClosureTable(std::string quantity, std::vector<double> solidFraction, std::string secondVariable,
               std::vector<double> second, std::vector<double> values);
  // 3-D table: values[(iz * second.size() + iy) * solidFraction.size() + ix] at
  // (solidFraction[ix], second[iy], third[iz]); a third axis needs a second one.
  ClosureTable(std::string quantity, std::vector<double> solidFraction, std::string secondVariable,
               std::vector<double> second, std::string thirdVariable, std::vector<double> third,
               std::vector<double> values);

  // The value at a state. `second` is ignored by a 1-D table, `third` by a table without a
  // third axis.
  [[nodiscard]] ClosureLookup operator()(double solidFraction, double second = 0.0, double third = 0.0) const;

  [[nodiscard]] const std::string& quantity() const { return quantity_; }
  [[nodiscard]] const std::string& secondVariable() const { return secondVariable_; }
  [[nodiscard]] bool twoDimensional() const { return !second_.empty(); }
  [[nodiscard]] const std::vector<double>& solidFractions() const { return solidFraction_; }
  [[nodiscard]] const std::vector<double>& seconds() const { return second_; }
  [[nodiscard]] const std::string& thirdVariable() const { return thirdVariable_; }
  [[nodiscard]] bool threeDimensional() const { return !third_.empty(); }
  [[nodiscard]] const std::vector<double>& thirds() const { return third_; }
  // values[(iz * seconds().size() + iy) * solidFractions().size() + ix], as constructed.
  [[nodiscard]] const std::vector<double>& values() const { return values_; }

 private:
  double alongSolidFraction(std::size_t row, double x) const;

  std::string quantity_;
  std::vector<double> solidFraction_;
  std::string secondVariable_;
  std::vector<double> second_;
  std::string thirdVariable_;
  std::vector<double> third_;
  std::vector<double> values_;
  std::vector<double> slopes_;  // d value / d solid fraction at each node, per row (PCHIP)
};

}  // namespace grainbridge::core
