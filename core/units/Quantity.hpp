#pragma once
// Reads a physical quantity from a config value: a bare number (in the config's unit system)
// or a string "<number> <unit>" in any unit udunits2 knows ("2.5 mm", "39 m/s", "2.7 g/cm3",
// "1.8e-5 Pa s", "8e5 dyne/cm", "26 degree"), converted to SI.
#include <nlohmann/json.hpp>
#include <string>
#include <variant>

#include "core/units/Dimension.hpp"
#include "core/units/UnitSystem.hpp"

namespace grainbridge::core::units {

// The SI value, or an error message saying what was expected and what was found.
using QuantityResult = std::variant<double, std::string>;

QuantityResult parseQuantity(const nlohmann::json& value, const Dimension& dim, const UnitSystem& system);

// Converts `number` in `unit` to the SI unit of `dim`; an error message if the unit is unknown
// or of another dimension.
QuantityResult convertToSI(double number, const std::string& unit, const Dimension& dim);

}  // namespace grainbridge::core::units
