#pragma once
// Numbers as people read them, and as machines read them back.
//
// Reports, logs, `status`, `db` tables and instance labels show `humanNumber` (six significant
// digits, no trailing zeros, short exponents: 0.013782299999999999 reads 0.0137823, 1e-06 reads
// 1e-6). Files a program reads back (CSV, JSON, the database) keep `roundTripText`, the
// shortest text that parses to the same double.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace grainbridge::core {

// Shortest decimal text that parses back to exactly `v` ("0.1", "1e-06" -> "1e-06").
std::string roundTripText(double v);

// `significant` digits (%g), trailing zeros dropped, exponent without padding ("1.5e-6").
std::string humanNumber(double v, int significant = 6);

// A mean with its standard error: the error to two significant digits, the mean to the same
// decimal place ("0.927 ± 0.024", "1.23e5 ± 4.1e3"); the mean alone when the error is not positive
// or below 1e-12 of the mean (rounding, not a measured error).
std::string humanWithError(double mean, double error);

// A JSON value for display: numbers through humanNumber, strings verbatim, a list as
// "[a, b]" and a list of one repeated value as "a (×3)" (a cubic box's three equal sides).
std::string humanText(const nlohmann::json& v, int significant = 6);

// A size in bytes with a decimal unit: "512 B", "4.52 MB".
std::string humanBytes(std::uintmax_t bytes);

}  // namespace grainbridge::core
