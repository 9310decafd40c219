#pragma once
// Whether two measured or configured values are the same one, to 1e-9 of the larger: what makes
// closure points "of the same grains" or "at the same restitution" after a trip through JSON,
// the database and unit conversion.
#include <algorithm>
#include <cmath>

namespace grainbridge::core {

[[nodiscard]] inline bool sameValue(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

}  // namespace grainbridge::core
