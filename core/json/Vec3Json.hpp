#pragma once
// A Vec3 in JSON: a list of three numbers [x, y, z], the form of every vector key of a config
// and of the engines' setups (box_lo, gravity, lengths, a region's corners).
#include <nlohmann/json.hpp>

#include "core/Types.hpp"

namespace grainbridge::core::json {

[[nodiscard]] inline nlohmann::json vec3Json(const Vec3& v) { return nlohmann::json::array({v[0], v[1], v[2]}); }
[[nodiscard]] inline Vec3 vec3FromJson(const nlohmann::json& j) {
  return Vec3(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>());
}

}  // namespace grainbridge::core::json
