#pragma once
// Reading back the CSV files stages write, in tests: a line's fields with RFC 4180 quoting (a
// run's label may hold commas).
#include <string>
#include <vector>

namespace grainbridge::testing {

// One CSV line's fields; a quoted field may hold commas and doubled quotes.
inline std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      out.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

}  // namespace grainbridge::testing
