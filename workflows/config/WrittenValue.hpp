#pragma once
// What the user wrote at a place in the config, for check messages. Stage checks run on the
// resolved parameters, so their numbers are SI ("lo along y is 0.0762 m"); a user who wrote
// "7.62 cm", or a bare number in reduced units, should also see their own writing.
#include <nlohmann/json.hpp>
#include <string>

#include "core/units/UnitSystem.hpp"

namespace grainbridge::workflows::config {

// " (written: [0, \"7.62 cm\", 0])" for the value at `pointer` of `document` when it holds a
// quantity with a unit or, in a reduced-unit config, a bare number ("..., bare numbers in reduced
// units"); "" when the value is SI as written, `message` already quotes it, it is not a scalar
// or an array of scalars, or it does not exist (a swept parameter, a key the defaults filled in).
std::string writtenNote(const nlohmann::json& document, const std::string& pointer, const std::string& message,
                        const core::units::UnitSystem& units);

}  // namespace grainbridge::workflows::config
