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
#include "workflows/params/ParamSpec.hpp"

namespace grainbridge::workflows::params {

class ParamSchema {
 public:
  ParamSchema& add(ParamSpec spec);
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

  // The resolved params that enter the stage key: those declared not to affect results dropped.
  [[nodiscard]] nlohmann::json keyParams(const nlohmann::json& resolved) const;

 private:
  std::vector<ParamSpec> specs_;
};

}  // namespace grainbridge::workflows::params
