#include "core/data/Materials.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace grainbridge::core::data {

std::optional<ContactMaterial> Materials::pair(std::int32_t a, std::int32_t b) const {
  for (const auto& p : pairs) {
    if ((p.speciesA == a && p.speciesB == b) || (p.speciesA == b && p.speciesB == a)) return p;
  }
  return std::nullopt;
}

Vec3 Materials::up() const { return gravity.norm() > 0.0 ? Vec3(-gravity.normalized()) : Vec3::UnitZ(); }

void Materials::validate() const {
  const auto n = static_cast<std::int32_t>(species.size());
  for (std::size_t s = 0; s < species.size(); ++s) {
    if (!(species[s].diameter > 0.0) || !(species[s].density > 0.0)) {
      throw Error("materials: species " + std::to_string(s) + " (" + species[s].name +
                  ") needs a positive diameter and density");
    }
  }
  auto check = [&](const ContactMaterial& c, const std::string& what) {
    if (c.speciesA < 0 || c.speciesA >= n || c.speciesB < 0 || c.speciesB >= n) {
      throw Error("materials: " + what + " names species " + std::to_string(c.speciesA) + ", " +
                  std::to_string(c.speciesB) + " of " + std::to_string(n));
    }
    if (!(c.restitution >= 0.0 && c.restitution <= 1.0) || !(c.friction >= 0.0)) {
      throw Error("materials: " + what + " has restitution " + std::to_string(c.restitution) + " and friction " +
                  std::to_string(c.friction) + " (need 0 <= e <= 1, mu >= 0)");
    }
  };
  for (std::size_t k = 0; k < pairs.size(); ++k) check(pairs[k], "pair " + std::to_string(k));
  for (std::size_t k = 0; k < walls.size(); ++k) {
    if (walls[k].wall < 0) throw Error("materials: wall entry " + std::to_string(k) + " has no wall index");
    check(walls[k], "wall entry " + std::to_string(k));
  }
}

}  // namespace grainbridge::core::data
