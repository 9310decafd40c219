#pragma once
// The declared parameters of one stage type, and their validation: a config's params object is
// checked key by key (unknown keys get a "did you mean"), values are converted to SI, ranges
// checked, defaults filled in. Every problem is added to the Diagnostics with its JSON pointer.
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/json/Diagnostics.hpp"
#include "core/units/UnitSystem.hpp"
#include "workflows/params/KeyRule.hpp"
#include "workflows/params/ParamSpec.hpp"

namespace grainbridge::workflows::params {

class ParamSchema {
 public:
  ParamSchema& add(ParamSpec spec);
  // Rules between keys of this object, declared after the keys they name (which must have no
  // default: a defaulted key is always present). Checked by checkRules; listed by
  // `grainbridge stages`. `why` says in a few words what the keys are for.
  ParamSchema& exactlyOneOf(std::vector<std::string> keys, std::string why = "");
  ParamSchema& atMostOneOf(std::vector<std::string> keys, std::string why = "");
  ParamSchema& requiresKey(std::string key, std::string needed, std::string why = "");
  ParamSchema& goTogether(std::vector<std::string> keys, std::string why = "");
  [[nodiscard]] const std::vector<KeyRule>& rules() const { return rules_; }
  [[nodiscard]] const std::vector<ParamSpec>& specs() const { return specs_; }
  [[nodiscard]] const ParamSpec* find(const std::string& name) const;
  [[nodiscard]] std::vector<std::string> names() const;
  // The declaration behind a path into nested parameters, "walls/1/mu" (an object list takes
  // an index), or nullptr with the reason in `error`. A plain name is a path of one step.
  [[nodiscard]] const ParamSpec* findPath(const std::string& path, std::string& error) const;

  // Resolves one value (SI number, integer, bool, string, list); nullopt after adding a
  // diagnostic at `pointer` if it is invalid.
  std::optional<nlohmann::json> resolveValue(const ParamSpec& spec, const nlohmann::json& value,
                                             const core::units::UnitSystem& units, const std::string& pointer,
                                             core::json::Diagnostics& diagnostics) const;

  // Resolves a params object. Names in `providedElsewhere` (swept parameters) are not required
  // here. Returns the resolved object with defaults filled in; keys sort, so dump() is canonical.
  nlohmann::json resolve(const nlohmann::json& params, const std::set<std::string>& providedElsewhere,
                         const core::units::UnitSystem& units, const std::string& pointer,
                         core::json::Diagnostics& diagnostics) const;

  // Checks the key rules of this schema and of every nested object present in `resolved`
  // (contact, each element of walls, ...), adding problems at `pointer` or below it. Run on
  // resolved params with any sweep point applied: a swept key counts as given.
  void checkRules(const nlohmann::json& resolved, const std::string& pointer,
                  core::json::Diagnostics& diagnostics) const;

  // The resolved params that enter the stage key: those declared not to affect results dropped.
  [[nodiscard]] nlohmann::json keyParams(const nlohmann::json& resolved) const;

 private:
  ParamSchema& addRule(KeyRule rule);

  std::vector<ParamSpec> specs_;
  std::vector<KeyRule> rules_;
};

}  // namespace grainbridge::workflows::params
