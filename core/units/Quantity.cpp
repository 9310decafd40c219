#include "core/units/Quantity.hpp"

#include <udunits2.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <mutex>

namespace grainbridge::core::units {

namespace {

// udunits2's unit database is loaded once per process (it parses several XML files).
ut_system* unitDatabase() {
  static ut_system* system = [] {
    ut_set_error_message_handler(ut_ignore);
    return ut_read_xml(nullptr);
  }();
  return system;
}

std::mutex& udunitsMutex() {
  static std::mutex m;  // udunits2 is not documented as thread-safe
  return m;
}

struct UnitDeleter {
  void operator()(ut_unit* u) const { ut_free(u); }
};
using UnitPtr = std::unique_ptr<ut_unit, UnitDeleter>;

}  // namespace

QuantityResult convertToSI(double number, const std::string& unit, const Dimension& dim) {
  std::lock_guard lock(udunitsMutex());
  ut_system* system = unitDatabase();
  if (system == nullptr)
    return std::string("the udunits2 unit database could not be loaded (is libudunits2-data installed?)");
  UnitPtr from(ut_parse(system, unit.c_str(), UT_UTF8));
  if (!from) return "unknown unit '" + unit + "'";
  UnitPtr to(dim.isNone() ? ut_get_dimensionless_unit_one(system) : ut_parse(system, dim.siUnit().c_str(), UT_ASCII));
  if (!to) return "internal: cannot parse SI unit '" + dim.siUnit() + "'";
  if (ut_are_convertible(from.get(), to.get()) == 0) {
    return "unit '" + unit + "' is not a unit of " +
           (dim.isNone() ? std::string("a dimensionless quantity") : "[" + dim.siUnit() + "]");
  }
  cv_converter* converter = ut_get_converter(from.get(), to.get());
  const double si = cv_convert_double(converter, number);
  cv_free(converter);
  return si;
}

QuantityResult parseQuantity(const nlohmann::json& value, const Dimension& dim, const UnitSystem& system) {
  const std::string expected = dim.isNone()
                                   ? std::string("a number")
                                   : "a number or a string \"<number> <unit>\" with a unit of [" + dim.siUnit() + "]";
  if (value.is_number()) {
    const double v = value.get<double>();
    if (!std::isfinite(v)) return "expected " + expected + ", found a non-finite number";
    return system.toSI(v, dim);
  }
  if (!value.is_string())
    return "expected " + expected + ", found " + std::string(value.type_name()) + " " + value.dump();
  const std::string text = value.get<std::string>();
  const char* begin = text.c_str();
  char* end = nullptr;
  const double number = std::strtod(begin, &end);
  if (end == begin || !std::isfinite(number)) return "expected " + expected + ", found \"" + text + "\"";
  std::string unit(end);
  const auto first = unit.find_first_not_of(" \t");
  if (first == std::string::npos) {
    return "expected " + expected + ", found \"" + text +
           "\" (a number in a string needs a unit; write it as a bare number to use the config's unit system)";
  }
  unit = unit.substr(first);
  QuantityResult converted = convertToSI(number, unit, dim);
  if (auto* err = std::get_if<std::string>(&converted)) return *err + " in \"" + text + "\"";
  return converted;
}

}  // namespace grainbridge::core::units
