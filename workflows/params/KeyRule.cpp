#include "workflows/params/KeyRule.hpp"

#include "core/Error.hpp"
#include "core/json/StrictParse.hpp"

namespace grainbridge::workflows::params {

namespace {

// "a", "a and b", "a, b and c".
std::string joinAnd(const std::vector<std::string>& words) {
  std::string s;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) s += i + 1 == words.size() ? " and " : ", ";
    s += words[i];
  }
  return s;
}

}  // namespace

KeyRule::KeyRule(Kind kind, std::vector<std::string> keys, std::string why)
    : kind_(kind), keys_(std::move(keys)), why_(std::move(why)) {
  GB_ASSERT(kind_ == Kind::Requires ? keys_.size() == 2 : keys_.size() >= 2,
            "a key rule names two keys or more (requires: exactly two)");
}

std::string KeyRule::description(const std::string& prefix) const {
  std::vector<std::string> names;
  for (const auto& k : keys_) names.push_back(prefix + k);
  std::string s;
  switch (kind_) {
    case Kind::ExactlyOneOf:
      s = "exactly one of " + joinAnd(names);
      break;
    case Kind::AtMostOneOf:
      s = "at most one of " + joinAnd(names);
      break;
    case Kind::Requires:
      s = names[0] + " requires " + names[1];
      break;
    case Kind::GoTogether:
      s = joinAnd(names) + " go together";
      break;
  }
  return why_.empty() ? s : s + " (" + why_ + ")";
}

void KeyRule::check(const nlohmann::json& object, const std::string& pointer,
                    core::json::Diagnostics& diagnostics) const {
  std::vector<std::string> given, missing;
  for (const auto& k : keys_) (object.contains(k) ? given : missing).push_back(k);
  const std::string why = why_.empty() ? "" : " (" + why_ + ")";
  auto foundGiven = [&] {
    if (given.empty()) return std::string("neither");
    if (given.size() == 2 && keys_.size() == 2) return std::string("both");
    return joinAnd(given);
  };
  switch (kind_) {
    case Kind::ExactlyOneOf:
      if (given.size() != 1) {
        diagnostics.add(pointer, "give exactly one of " + joinAnd(keys_) + why + ", found " + foundGiven());
      }
      break;
    case Kind::AtMostOneOf:
      if (given.size() > 1) {
        diagnostics.add(pointer, "give at most one of " + joinAnd(keys_) + why + ", found " + foundGiven());
      }
      break;
    case Kind::Requires:
      if (object.contains(keys_[0]) && !object.contains(keys_[1])) {
        diagnostics.add(pointer + "/" + core::json::pointerToken(keys_[0]),
                        keys_[0] + " requires " + keys_[1] + why + ", which is not given");
      }
      break;
    case Kind::GoTogether:
      if (!given.empty() && !missing.empty()) {
        diagnostics.add(
            pointer + "/" + core::json::pointerToken(missing.front()),
            joinAnd(keys_) + " go together" + why + ": " + joinAnd(given) + " given without " + joinAnd(missing));
      }
      break;
  }
}

}  // namespace grainbridge::workflows::params
