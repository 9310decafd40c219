#pragma once
// A rule between keys of one params object (two alternatives, a key that needs another),
// declared once on its ParamSchema beside the keys themselves (STYLE.md 5): the check at load,
// the `grainbridge stages` listing and docs/stages.md all come from this one declaration.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/json/Diagnostics.hpp"

namespace grainbridge::workflows::params {

class KeyRule {
 public:
  enum class Kind {
    ExactlyOneOf,  // one alternative, and only one (gamma_n or restitution)
    AtMostOneOf,   // alternatives that exclude each other, none needed (lammps_data, initial_frame)
    Requires,      // keys[0] is only meaningful with keys[1]
    GoTogether,    // all of them or none
  };

  // `why` is a few words on what the keys are for ("the initial state"); it is added to the
  // message and the listing.
  KeyRule(Kind kind, std::vector<std::string> keys, std::string why = "");

  [[nodiscard]] Kind kind() const { return kind_; }
  [[nodiscard]] const std::vector<std::string>& keys() const { return keys_; }
  // "exactly one of contact.gamma_n, contact.restitution"; `prefix` names the object the keys
  // sit in ("contact.", "walls[].").
  [[nodiscard]] std::string description(const std::string& prefix = "") const;
  // Checks one resolved params object at `pointer`; a key counts as given when it is present
  // (the rule's keys have no defaults, so a present key is one the config gave).
  void check(const nlohmann::json& object, const std::string& pointer, core::json::Diagnostics& diagnostics) const;

 private:
  Kind kind_;
  std::vector<std::string> keys_;
  std::string why_;
};

}  // namespace grainbridge::workflows::params
