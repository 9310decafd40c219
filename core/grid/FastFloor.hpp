#pragma once
// floor() without the libm call: the build targets baseline x86-64 (no SSE4.1 roundsd), where
// std::floor is a function call, and cell lookups take several floors per particle and per
// contact segment. Both give exactly std::floor's value.
#include <cmath>
#include <cstdint>

namespace grainbridge::core::grid {

// static_cast<int>(std::floor(x)) for x within the range of int (beyond it both are undefined).
inline int floorToInt(double x) {
  const int i = static_cast<int>(x);  // rounds toward zero
  return i > x ? i - 1 : i;
}

// std::floor(x) for every double, -0.0, infinities and NaN included.
inline double floorExact(double x) {
  // From 2^52 on every double is an integer (and infinities and NaN fail the test).
  if (!(std::abs(x) < 4503599627370496.0)) return x;
  const auto t = static_cast<double>(static_cast<std::int64_t>(x));
  if (t == x) return x;  // integral: keeps the sign of -0.0
  return t > x ? t - 1.0 : t;
}

}  // namespace grainbridge::core::grid
