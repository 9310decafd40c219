#pragma once
// Reads back a numeric CSV a stage wrote (an engine's series.csv): one header line of column
// names, then rows of numbers. Comparing stages plot columns of it against time.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace grainbridge::workflows::contract {

// The columns by name. Throws grainbridge::Error naming the file and line when a row has a
// different number of fields than the header or a field that is not a number.
std::map<std::string, std::vector<double>> readNumericCsv(const std::filesystem::path& file);

}  // namespace grainbridge::workflows::contract
