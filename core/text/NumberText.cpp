#include "core/text/NumberText.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace grainbridge::core {

std::string roundTripText(double v) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, v);
  return {buf, result.ptr};
}

std::string humanNumber(double v, int significant) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  std::string s = buf;
  // %g already drops trailing zeros of the mantissa; tidy the exponent: e-06 -> e-6, e+07 -> e7.
  const auto e = s.find('e');
  if (e == std::string::npos) return s == "-0" ? "0" : s;
  std::string mantissa = s.substr(0, e);
  const char sign = s[e + 1];
  std::size_t digits = e + 2;
  while (digits + 1 < s.size() && s[digits] == '0') ++digits;
  return mantissa + "e" + (sign == '-' ? "-" : "") + s.substr(digits);
}

std::string humanWithError(double mean, double error) {
  if (!(error > 0.0) || !std::isfinite(error) || !std::isfinite(mean)) return humanNumber(mean);
  // An error at the level of the mean's rounding (a constant series' block error) says nothing,
  // and its digits would be beyond a double's precision.
  if (error < 1e-12 * std::abs(mean)) return humanNumber(mean);
  // The error's second significant digit sets the last digit shown.
  const int lastDigit = static_cast<int>(std::floor(std::log10(error))) - 1;
  const double magnitude = std::max(std::abs(mean), error);
  if (lastDigit < 0 && lastDigit >= -8 && magnitude >= 1e-3 && magnitude < 1e6) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f ± %.*f", -lastDigit, mean, -lastDigit, error);
    return buf;
  }
  const int meanDigits = std::max(2, static_cast<int>(std::floor(std::log10(magnitude))) - lastDigit + 1);
  return humanNumber(mean, meanDigits) + " ± " + humanNumber(error, 2);
}

std::string humanText(const nlohmann::json& v, int significant) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) return humanNumber(v.get<double>(), significant);
  if (v.is_array()) {
    if (v.empty()) return "[]";
    bool allEqual = v.size() > 1;
    for (const auto& x : v) allEqual = allEqual && x == v.front();
    if (allEqual) return humanText(v.front(), significant) + " (×" + std::to_string(v.size()) + ")";
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + humanText(v[i], significant);
    return out + "]";
  }
  return v.dump();
}

std::string humanBytes(std::uintmax_t bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB"};
  double v = static_cast<double>(bytes);
  int u = 0;
  while (v >= 1000.0 && u < 4) {
    v /= 1000.0;
    ++u;
  }
  return humanNumber(v, u == 0 ? 6 : 3) + " " + units[u];
}

}  // namespace grainbridge::core
