#pragma once
// `grainbridge report validation`: every VALIDATION.md figure reached so far on one HTML page —
// reference value, ours, deviation, pass or not. Two sources: the records the physics tests
// leave (tests/support/ValidationRecord.hpp, one JSON file per check), and closure databases
// of workflow runs (kinetic-theory comparisons, Brazil-nut force statistics and structure),
// whose figures VALIDATION.md asks to report rather than assert.
#include <filesystem>
#include <vector>

namespace grainbridge::workflows::report {

struct ValidationSources {
  std::filesystem::path recordsDir;              // may be empty or missing: no test records
  std::vector<std::filesystem::path> databases;  // grainbridge.sqlite files of workflow runs
};

struct ValidationSummary {
  int checks = 0, passed = 0, failed = 0, reported = 0;
};

// Writes the page to `out` (and a CSV next to it, same name with .csv). Throws
// grainbridge::Error naming a record file that is not valid JSON.
ValidationSummary writeValidationReport(const ValidationSources& sources, const std::filesystem::path& out);

}  // namespace grainbridge::workflows::report
