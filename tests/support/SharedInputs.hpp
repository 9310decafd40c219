#pragma once
// Shipped configs that read inputs from ../shared (the LAMMPS chute bed, beside the clone in CI
// and on the project's machines): a clone elsewhere has no such folder, and its tests skip those
// configs instead of failing on a missing input file.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace grainbridge::testing {

// True when the config at `config` (a path in `sourceRoot`) names a file under ../shared and
// that folder is not beside `sourceRoot`.
inline bool needsMissingSharedInputs(const std::filesystem::path& sourceRoot, const std::filesystem::path& config) {
  std::ifstream in(config);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return text.find("../shared/") != std::string::npos && !std::filesystem::exists(sourceRoot / ".." / "shared");
}

}  // namespace grainbridge::testing
