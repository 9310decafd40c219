#include "workflows/contract/NumericCsv.hpp"

#include <cstdlib>
#include <sstream>

#include "core/Error.hpp"
#include "core/Files.hpp"

namespace grainbridge::workflows::contract {

namespace {

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

}  // namespace

std::map<std::string, std::vector<double>> readNumericCsv(const std::filesystem::path& file) {
  std::istringstream lines(core::readFile(file));
  std::string line;
  if (!std::getline(lines, line)) throw Error(file.string() + ": empty, expected a header line");
  const auto names = fields(line);
  std::map<std::string, std::vector<double>> columns;
  for (const auto& n : names) columns[n];
  for (int number = 2; std::getline(lines, line); ++number) {
    if (line.empty()) continue;
    const auto values = fields(line);
    if (values.size() != names.size()) {
      throw Error(file.string() + ":" + std::to_string(number) + ": " + std::to_string(values.size()) +
                  " fields, the header has " + std::to_string(names.size()));
    }
    for (std::size_t k = 0; k < names.size(); ++k) {
      const char* begin = values[k].c_str();
      char* end = nullptr;
      const double v = std::strtod(begin, &end);
      if (end == begin || *end != '\0') {
        throw Error(file.string() + ":" + std::to_string(number) + ": column " + names[k] + " holds \"" + values[k] +
                    "\", not a number");
      }
      columns[names[k]].push_back(v);
    }
  }
  return columns;
}

}  // namespace grainbridge::workflows::contract
