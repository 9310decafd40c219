#include "core/units/Dimension.hpp"

namespace grainbridge::core::units {

std::string Dimension::siUnit() const {
  std::string out;
  auto term = [&out](const char* symbol, int exponent) {
    if (exponent == 0) return;
    if (!out.empty()) out += ' ';
    out += symbol;
    if (exponent != 1) out += std::to_string(exponent);
  };
  term("kg", mass);
  term("m", length);
  term("s", time);
  return out.empty() ? "1" : out;
}

}  // namespace grainbridge::core::units
