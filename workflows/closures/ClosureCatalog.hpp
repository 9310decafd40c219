#pragma once
// Every continuum closure of engines/closures as a user and a stage see it: its name, equations
// and source, its parameters (the schema fragment the mfm and tfdem stages include, so a law's
// parameters are declared once, with units and ranges) and the state it is evaluated at. The
// `grainbridge closures` calculator evaluates a law through the same engines/closures code an
// engine calls; docs/closures.md is generated from this catalog.
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "workflows/params/ParamSchema.hpp"

namespace grainbridge::workflows::closures {

struct ClosureOutput {
  std::string name;
  std::string unit;  // SI, "" for dimensionless
  double value = 0.0;
};

struct ClosureEntry {
  std::string name;                             // snake case, as configs name it
  std::string summary;                          // one line
  std::string equations;                        // "Eqs. 3.10-3.16"
  std::string source;                           // literature and the implementation it was checked against
  std::shared_ptr<params::ParamSchema> params;  // the law's parameters (a stage's schema fragment)
  std::shared_ptr<params::ParamSchema> inputs;  // the state it is evaluated at
  // Resolved (SI) params and inputs -> outputs. Throws grainbridge::Error for values the law
  // refuses (out of range, a parameter set it cannot use).
  std::function<std::vector<ClosureOutput>(const nlohmann::json& params, const nlohmann::json& inputs)> evaluate;
  // Rules on the parameters that a schema cannot declare (Eq. 3.14 for C and D, an angle that
  // cannot be in radians): why the resolved params cannot be used, or "". A stage that includes
  // the fragment calls it from its checkParams, so the problem is reported at load.
  std::function<std::string(const nlohmann::json& params)> checkParams = [](const nlohmann::json&) {
    return std::string();
  };
};

// Every law, in the order the docs list them.
const std::vector<ClosureEntry>& closureCatalog();
// nullptr when no law has that name.
const ClosureEntry* findClosure(std::string_view name);
// The declaration of parameter `key` of law `law`, for a stage to include (renamed to its config
// key where the two differ); throws grainbridge::Error naming both when there is none.
params::ParamSpec closureParameter(std::string_view law, const std::string& key);

}  // namespace grainbridge::workflows::closures
