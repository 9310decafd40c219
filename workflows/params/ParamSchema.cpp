#include "workflows/params/ParamSchema.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "core/Error.hpp"
#include "core/Sha256.hpp"
#include "core/json/StrictParse.hpp"
#include "core/units/Quantity.hpp"

namespace grainbridge::workflows::params {

using nlohmann::json;
namespace cj = core::json;

ParamSchema& ParamSchema::add(ParamSpec spec) {
  GB_ASSERT(find(spec.name()) == nullptr, "parameter '" + spec.name() + "' declared twice");
  if (spec.defaultJson()) {
    // A default must itself be valid: catching a bad declaration here beats a confusing
    // error in every config that relies on it.
    cj::Diagnostics d;
    resolveValue(spec, *spec.defaultJson(), core::units::UnitSystem::si(), "default of " + spec.name(), d);
    GB_ASSERT(d.empty(), d.format("parameter declaration"));
  }
  specs_.push_back(std::move(spec));
  return *this;
}

ParamSchema& ParamSchema::addRule(KeyRule rule) {
  for (const auto& key : rule.keys()) {
    const ParamSpec* spec = find(key);
    GB_ASSERT(spec != nullptr, "key rule '" + rule.description() + "' names undeclared parameter '" + key + "'");
    GB_ASSERT(!spec->defaultJson() && !spec->isRequired(),
              "key rule '" + rule.description() + "' names '" + key + "', which is always given (default or required)");
  }
  rules_.push_back(std::move(rule));
  return *this;
}
ParamSchema& ParamSchema::exactlyOneOf(std::vector<std::string> keys, std::string why) {
  return addRule(KeyRule(KeyRule::Kind::ExactlyOneOf, std::move(keys), std::move(why)));
}
ParamSchema& ParamSchema::atMostOneOf(std::vector<std::string> keys, std::string why) {
  return addRule(KeyRule(KeyRule::Kind::AtMostOneOf, std::move(keys), std::move(why)));
}
ParamSchema& ParamSchema::requiresKey(std::string key, std::string needed, std::string why) {
  return addRule(KeyRule(KeyRule::Kind::Requires, {std::move(key), std::move(needed)}, std::move(why)));
}
ParamSchema& ParamSchema::goTogether(std::vector<std::string> keys, std::string why) {
  return addRule(KeyRule(KeyRule::Kind::GoTogether, std::move(keys), std::move(why)));
}

void ParamSchema::checkRules(const json& resolved, const std::string& pointer, cj::Diagnostics& diagnostics) const {
  if (!resolved.is_object()) return;  // reported by resolve
  for (const auto& rule : rules_) rule.check(resolved, pointer, diagnostics);
  for (const auto& spec : specs_) {
    if (spec.nested() == nullptr || !resolved.contains(spec.name())) continue;
    const json& value = resolved.at(spec.name());
    const std::string where = pointer + "/" + cj::pointerToken(spec.name());
    if (spec.kind() == ParamKind::Object) {
      spec.nested()->checkRules(value, where, diagnostics);
    } else if (value.is_array()) {
      for (std::size_t i = 0; i < value.size(); ++i) {
        spec.nested()->checkRules(value[i], where + "/" + std::to_string(i), diagnostics);
      }
    }
  }
}

const ParamSpec* ParamSchema::find(const std::string& name) const {
  for (const auto& s : specs_) {
    if (s.name() == name) return &s;
  }
  return nullptr;
}

const ParamSpec* ParamSchema::findPath(const std::string& path, std::string& error) const {
  const ParamSchema* schema = this;
  const ParamSpec* spec = nullptr;
  bool needIndex = false;  // the previous step was an object list: an element index comes next
  std::size_t start = 0;
  while (true) {
    const std::size_t slash = path.find('/', start);
    const std::string token = path.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
    if (needIndex) {
      if (token.empty() || token.find_first_not_of("0123456789") != std::string::npos) {
        error = "expected an element index after \"" + spec->name() + "/\", found \"" + token + "\"";
        return nullptr;
      }
      needIndex = false;
    } else {
      if (schema == nullptr) {
        error = "\"" + spec->name() + "\" has no fields";
        return nullptr;
      }
      spec = schema->find(token);
      if (spec == nullptr) {
        error = "unknown parameter \"" + token + "\"";
        const auto hint = core::json::closestMatch(token, schema->names());
        if (!hint.empty()) error += " (did you mean \"" + hint + "\"?)";
        return nullptr;
      }
      schema = spec->nested();
      needIndex = spec->kind() == ParamKind::ObjectList;
    }
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  if (spec->kind() == ParamKind::Object || spec->kind() == ParamKind::ObjectList || needIndex) {
    error = "\"" + path + "\" is a whole object; sweep one of its fields";
    return nullptr;
  }
  return spec;
}

std::vector<std::string> ParamSchema::names() const {
  std::vector<std::string> out;
  for (const auto& s : specs_) out.push_back(s.name());
  return out;
}

namespace {

std::string found(const json& value) { return cj::describeFound(value.dump(), value.type_name()); }

bool checkRange(const ParamSpec& spec, double v, const std::string& pointer, cj::Diagnostics& diagnostics) {
  const auto& lo = spec.lower();
  const auto& hi = spec.upper();
  const bool belowMin = lo && (lo->inclusive ? v < lo->value : v <= lo->value);
  const bool aboveMax = hi && (hi->inclusive ? v > hi->value : v >= hi->value);
  if (!belowMin && !aboveMax) return true;
  std::ostringstream msg;
  msg << "expected " << spec.name() << " " << spec.rangeDescription();
  if (!spec.dimension().isNone()) msg << " (SI, " << spec.dimension().siUnit() << ")";
  msg << ", found " << v;
  diagnostics.add(pointer, msg.str());
  return false;
}

std::optional<double> resolveQuantity(const ParamSpec& spec, const json& value, const core::units::UnitSystem& units,
                                      const std::string& pointer, cj::Diagnostics& diagnostics) {
  auto r = core::units::parseQuantity(value, spec.dimension(), units);
  if (auto* err = std::get_if<std::string>(&r)) {
    diagnostics.add(pointer, *err);
    return std::nullopt;
  }
  const double v = std::get<double>(r);
  if (!checkRange(spec, v, pointer, diagnostics)) return std::nullopt;
  return v;
}

std::optional<std::int64_t> resolveInteger(const ParamSpec& spec, const json& value, const std::string& pointer,
                                           cj::Diagnostics& diagnostics) {
  // 3.0 is accepted as 3 (JSON writers differ), 3.5 is not.
  const bool integral = value.is_number_integer() || (value.is_number_float() && std::isfinite(value.get<double>()) &&
                                                      value.get<double>() == std::floor(value.get<double>()) &&
                                                      std::abs(value.get<double>()) < 9.0e15);
  if (!integral) {
    diagnostics.add(pointer, "expected an integer, found " + found(value));
    return std::nullopt;
  }
  const auto v = value.is_number_integer() ? value.get<std::int64_t>() : static_cast<std::int64_t>(value.get<double>());
  if (!checkRange(spec, static_cast<double>(v), pointer, diagnostics)) return std::nullopt;
  return v;
}

// A list of the declared length (any length when 0) whose elements `element` resolves, each at
// its own pointer; nullopt once any element or the length is wrong.
template <class ResolveElement>
std::optional<json> resolveList(const ParamSpec& spec, const json& value, const std::string& pointer,
                                cj::Diagnostics& diagnostics, ResolveElement&& element) {
  if (!value.is_array() || (spec.listLength() > 0 && static_cast<int>(value.size()) != spec.listLength())) {
    diagnostics.add(pointer, "expected a " + spec.typeDescription() + ", found " + found(value));
    return std::nullopt;
  }
  json out = json::array();
  bool ok = true;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (const std::optional<double> v = element(value[i], pointer + "/" + std::to_string(i)))
      out.push_back(*v);
    else
      ok = false;
  }
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace

std::optional<json> ParamSchema::resolveValue(const ParamSpec& spec, const json& value,
                                              const core::units::UnitSystem& units, const std::string& pointer,
                                              cj::Diagnostics& diagnostics) const {
  switch (spec.kind()) {
    case ParamKind::Quantity: {
      auto v = resolveQuantity(spec, value, units, pointer, diagnostics);
      if (!v) return std::nullopt;
      return json(*v);
    }
    case ParamKind::Integer: {
      const auto v = resolveInteger(spec, value, pointer, diagnostics);
      if (!v) return std::nullopt;
      return json(*v);
    }
    case ParamKind::Boolean:
      if (!value.is_boolean()) {
        diagnostics.add(pointer, "expected true or false, found " + found(value));
        return std::nullopt;
      }
      return value;
    case ParamKind::String: {
      if (!value.is_string()) {
        diagnostics.add(pointer, "expected a string, found " + found(value));
        return std::nullopt;
      }
      const auto& allowed = spec.allowed();
      const auto s = value.get<std::string>();
      if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), s) == allowed.end()) {
        std::string msg = "expected " + spec.typeDescription() + ", found \"" + s + "\"";
        const auto hint = cj::closestMatch(s, allowed);
        if (!hint.empty()) msg += " (did you mean \"" + hint + "\"?)";
        diagnostics.add(pointer, msg);
        return std::nullopt;
      }
      return value;
    }
    case ParamKind::StringList: {
      if (!value.is_array()) {
        diagnostics.add(pointer, "expected a list of strings, found " + found(value));
        return std::nullopt;
      }
      const auto& allowed = spec.allowed();
      const std::size_t before = diagnostics.size();
      std::vector<std::string> seen;
      for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string where = pointer + "/" + std::to_string(i);
        if (!value[i].is_string()) {
          diagnostics.add(where, "expected a string, found " + found(value[i]));
          continue;
        }
        const auto s = value[i].get<std::string>();
        if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), s) == allowed.end()) {
          std::string msg = "expected one of ";
          for (std::size_t k = 0; k < allowed.size(); ++k) msg += (k ? "|" : "") + allowed[k];
          msg += ", found \"" + s + "\"";
          const auto hint = cj::closestMatch(s, allowed);
          if (!hint.empty()) msg += " (did you mean \"" + hint + "\"?)";
          diagnostics.add(where, msg);
        } else if (std::find(seen.begin(), seen.end(), s) != seen.end()) {
          diagnostics.add(where, "\"" + s + "\" is listed twice");
        }
        seen.push_back(s);
      }
      if (diagnostics.size() != before) return std::nullopt;
      return value;
    }
    case ParamKind::InputFile: {
      if (!value.is_string() || value.get<std::string>().empty()) {
        diagnostics.add(pointer, "expected a file path, found " + found(value));
        return std::nullopt;
      }
      const std::string path = value.get<std::string>();
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec)) {
        diagnostics.add(pointer,
                        "cannot read file '" + path + "' (relative paths start at the folder grainbridge runs in)");
        return std::nullopt;
      }
      try {
        return json{{"path", path}, {"sha256", core::sha256FileOncePerVersion(path)}};
      } catch (const Error& e) {
        diagnostics.add(pointer, e.what());
        return std::nullopt;
      }
    }
    case ParamKind::Object: {
      const std::size_t before = diagnostics.size();
      json out = spec.nested()->resolve(value, {}, units, pointer, diagnostics);
      if (diagnostics.size() != before) return std::nullopt;
      return out;
    }
    case ParamKind::ObjectList: {
      if (!value.is_array() || value.empty()) {
        diagnostics.add(pointer, "expected a non-empty list of objects, found " + found(value));
        return std::nullopt;
      }
      const std::size_t before = diagnostics.size();
      json out = json::array();
      for (std::size_t i = 0; i < value.size(); ++i) {
        out.push_back(spec.nested()->resolve(value[i], {}, units, pointer + "/" + std::to_string(i), diagnostics));
      }
      if (diagnostics.size() != before) return std::nullopt;
      return out;
    }
    case ParamKind::IntegerList:
      // Stored as doubles (see ParamSpec::integerList): exact up to 2^53, far beyond any id.
      return resolveList(spec, value, pointer, diagnostics, [&](const json& element, const std::string& where) {
        const auto v = resolveInteger(spec, element, where, diagnostics);
        return v ? std::optional<double>(static_cast<double>(*v)) : std::nullopt;
      });
    case ParamKind::QuantityList:
      return resolveList(spec, value, pointer, diagnostics, [&](const json& element, const std::string& where) {
        return resolveQuantity(spec, element, units, where, diagnostics);
      });
  }
  return std::nullopt;
}

json ParamSchema::resolve(const json& params, const std::set<std::string>& providedElsewhere,
                          const core::units::UnitSystem& units, const std::string& pointer,
                          cj::Diagnostics& diagnostics) const {
  json resolved = json::object();
  if (!params.is_object()) {
    diagnostics.add(pointer, "expected an object of parameters, found " + found(params));
    return resolved;
  }
  const auto known = names();
  for (const auto& [key, value] : params.items()) {
    const std::string where = pointer + "/" + cj::pointerToken(key);
    const ParamSpec* spec = find(key);
    if (spec == nullptr) {
      std::string msg = "unknown parameter \"" + key + "\"";
      const auto hint = cj::closestMatch(key, known);
      msg += hint.empty() ? " (see `grainbridge stages` for the parameters of each stage type)"
                          : " (did you mean \"" + hint + "\"?)";
      diagnostics.add(where, msg);
      continue;
    }
    if (auto v = resolveValue(*spec, value, units, where, diagnostics)) resolved[key] = *v;
  }
  for (const auto& spec : specs_) {
    if (params.contains(spec.name()) || providedElsewhere.count(spec.name()) != 0) continue;
    if (spec.isRequired()) {
      diagnostics.add(pointer, "missing required parameter \"" + spec.name() + "\" (" + spec.typeDescription() + ": " +
                                   spec.docText() + ")");
    } else if (spec.defaultJson()) {
      cj::Diagnostics ignored;  // defaults were validated at declaration
      if (auto v = resolveValue(spec, *spec.defaultJson(), core::units::UnitSystem::si(), pointer, ignored))
        resolved[spec.name()] = *v;
    }
  }
  return resolved;
}

json ParamSchema::keyParams(const json& resolved) const {
  json out = json::object();
  for (const auto& [key, value] : resolved.items()) {
    const ParamSpec* spec = find(key);
    if (spec != nullptr && spec->kind() == ParamKind::InputFile)
      out[key] = value.at("sha256");  // content, not place
    else if (spec == nullptr || spec->affectsResults())
      out[key] = value;
  }
  return out;
}

}  // namespace grainbridge::workflows::params
