#pragma once
// One CSV field as RFC 4180 writes it: quoted (with doubled quotes) only when it holds a comma,
// a quote or a newline. Shared by every CSV the reports and the db commands write.
#include <sstream>
#include <string>

namespace grainbridge::workflows::report {

inline std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// A number with 12 significant digits, the precision of every numeric CSV column we write.
inline std::string csvNumber(double v) {
  std::ostringstream out;
  out.precision(12);
  out << v;
  return out.str();
}

}  // namespace grainbridge::workflows::report
