#pragma once
// The drag law of a resolved mfm or tfdem stage config, read and checked in one call: the law
// `drag` names with the values of its stage keys (DragSchema.hpp declares them), its problem
// reported at the key to change. The engines' set-ups read the two halves apart
// (engines/closures/DragFromJson.hpp); this is the one-call form for a law list chosen by a test.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "engines/closures/DragFromJson.hpp"

namespace grainbridge::workflows::stages {

template <class Laws = grainbridge::closures::DragLaws>
grainbridge::closures::GasSolidsDragOf<Laws> dragFromParams(
    const nlohmann::json& p, const std::function<void(const std::string&, const std::string&)>& problem) {
  auto drag = grainbridge::closures::dragFromJson<Laws>(p);
  if (const auto found = grainbridge::closures::dragProblem<Laws>(drag)) problem(found->pointer, found->message);
  return drag;
}

}  // namespace grainbridge::workflows::stages
