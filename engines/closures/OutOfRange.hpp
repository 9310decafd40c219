#pragma once
// The one way a closure refuses an input or parameter out of its range: a grainbridge::Error
// "<law>: <what> must be <expected>, got <value>", the value with 10 significant digits (NaN
// included), so every law names the offending quantity the same way.
#include <string_view>

namespace grainbridge::closures {

[[noreturn]] void refuseValue(std::string_view law, std::string_view what, std::string_view expected, double value);

}  // namespace grainbridge::closures
