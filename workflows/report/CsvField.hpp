#pragma once
// One CSV field as RFC 4180 writes it: quoted (with doubled quotes) only when it holds a comma,
// a quote or a newline. Shared by every CSV the reports and the db commands write.
#include <nlohmann/json.hpp>
#include <string>

#include "core/text/NumberText.hpp"

namespace grainbridge::workflows::report {

inline std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// A JSON value as one CSV field at full precision (CSVs are read by programs; people read the
// report's tables, core/text/NumberText): empty for null, a number as the shortest text that
// reads back as the same double, a string as written, anything else as JSON.
inline std::string csvValue(const nlohmann::json& v) {
  if (v.is_null()) return {};
  if (v.is_number_float()) return core::roundTripText(v.get<double>());
  return csvField(v.is_string() ? v.get<std::string>() : v.dump());
}

}  // namespace grainbridge::workflows::report
