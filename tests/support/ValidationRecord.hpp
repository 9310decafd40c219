#pragma once
// Physics tests leave a record of every VALIDATION.md figure they check: the reference value,
// ours, the tolerance and whether it passed. `grainbridge report validation` gathers these
// records (and the closure database's comparisons) into one HTML page, so the figures reached
// so far are readable without digging through test logs. One JSON file per check, written
// atomically, into GRAINBRIDGE_VALIDATION_DIR (set by CMake to <build>/validation; the
// environment variable of the same name overrides it).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace grainbridge::testing {

struct ValidationCheck {
  std::string id;         // file name and sort key, e.g. "dem.restitution.small_small"
  std::string section;    // VALIDATION.md section, e.g. "DEM (Chapter 6)"
  std::string check;      // what is compared, e.g. "restitution of the linear model, small-small"
  std::string reference;  // where the reference value comes from, e.g. "Eqs. 6.9-6.10, Table 6.1"
  double referenceValue = 0.0;
  double ours = 0.0;
  std::string tolerance;  // as VALIDATION.md states it, e.g. "1 %"
  bool passed = false;
  std::string note;
};

inline void recordValidation(const ValidationCheck& c) {
  const char* env = std::getenv("GRAINBRIDGE_VALIDATION_DIR");
#ifdef GRAINBRIDGE_VALIDATION_DIR
  const std::filesystem::path dir = env != nullptr ? env : GRAINBRIDGE_VALIDATION_DIR;
#else
  if (env == nullptr) return;
  const std::filesystem::path dir = env;
#endif
  std::filesystem::create_directories(dir);
  const nlohmann::json record = {{"id", c.id},
                                 {"section", c.section},
                                 {"check", c.check},
                                 {"reference", c.reference},
                                 {"reference_value", c.referenceValue},
                                 {"ours", c.ours},
                                 {"deviation", c.referenceValue != 0.0 ? (c.ours - c.referenceValue) / c.referenceValue
                                                                       : c.ours - c.referenceValue},
                                 {"tolerance", c.tolerance},
                                 {"passed", c.passed},
                                 {"note", c.note}};
  const auto tmp = dir / (c.id + ".json.tmp");
  {
    std::ofstream out(tmp);
    out << record.dump(2) << "\n";
  }
  std::filesystem::rename(tmp, dir / (c.id + ".json"));
}

}  // namespace grainbridge::testing
