#pragma once
// One CSV field as RFC 4180 writes it: quoted (with doubled quotes) only when it holds a comma,
// a quote or a newline. Shared by every CSV the reports and the db commands write.
#include <string>

#include "core/text/NumberText.hpp"

namespace grainbridge::workflows::report {

inline std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// A number at full precision (the shortest text that reads back as the same double): CSVs are
// read by programs; people read the report's tables (core/text/NumberText's humanNumber).
inline std::string csvNumber(double v) { return core::roundTripText(v); }

}  // namespace grainbridge::workflows::report
