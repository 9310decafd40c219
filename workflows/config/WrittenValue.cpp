#include "workflows/config/WrittenValue.hpp"

#include <cctype>
#include <cstdlib>

namespace grainbridge::workflows::config {

using nlohmann::json;

namespace {

// "7.62 cm", "1e-4 s": a number followed by a unit (the form core::units::parseQuantity reads);
// not a name such as "random" or "syamlal_obrien".
bool isQuantityWithUnit(const json& v) {
  if (!v.is_string()) return false;
  const std::string& s = v.get_ref<const std::string&>();
  const char* begin = s.c_str();
  char* end = nullptr;
  std::strtod(begin, &end);
  if (end == begin) return false;
  for (const char* c = end; *c != '\0'; ++c) {
    if (std::isspace(static_cast<unsigned char>(*c)) == 0) return true;
  }
  return false;
}

}  // namespace

std::string writtenNote(const json& document, const std::string& pointer, const std::string& message,
                        const core::units::UnitSystem& units) {
  const json* value = nullptr;
  try {
    const json::json_pointer at(pointer);
    if (!document.contains(at)) return "";
    value = &document.at(at);
  } catch (const json::exception&) {
    return "";  // not a pointer into the document
  }
  const json elements = value->is_array() ? *value : json::array({*value});
  bool unitWritten = false, bareReduced = false;
  for (const auto& e : elements) {
    if (e.is_structured()) return "";
    // "is -1.035 m/s" quotes "-1.035 m/s" already: only a unit the message does not show needs it.
    unitWritten =
        unitWritten || (isQuantityWithUnit(e) && message.find(e.get_ref<const std::string&>()) == std::string::npos);
    bareReduced = bareReduced || (units.isReduced() && e.is_number());
  }
  if (!unitWritten && !bareReduced) return "";
  return " (written: " + value->dump() + (bareReduced ? ", bare numbers in reduced units" : "") + ")";
}

}  // namespace grainbridge::workflows::config
