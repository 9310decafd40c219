#include "core/data/ParticleFrame.hpp"

#include <string>

#include "core/Error.hpp"

namespace grainbridge::core::data {

namespace {
template <class T>
void checkLength(const std::vector<T>& v, const char* name, std::size_t expected) {
  if (v.size() != expected) {
    throw Error("particle array '" + std::string(name) + "' has " + std::to_string(v.size()) + " entries, expected " +
                std::to_string(expected) + " (the length of 'id')");
  }
}
}  // namespace

void ParticleFrame::validate() const {
  try {
    const std::size_t n = id.size();
    checkLength(species, "species", n);
    checkLength(radius, "radius", n);
    checkLength(mass, "mass", n);
    checkLength(position, "position", n);
    checkLength(velocity, "velocity", n);
    checkLength(angularVelocity, "angularVelocity", n);
    if (!externalForce.empty()) checkLength(externalForce, "externalForce", n);
    for (std::size_t w = 0; w < domain.walls.size(); ++w) {
      const Wall& wall = domain.walls[w];
      if (wall.kind != "plane" && wall.kind != "cylinder") {
        throw Error("wall " + std::to_string(w) + " has kind '" + wall.kind + "', expected 'plane' or 'cylinder'");
      }
    }
    contacts.validate();
    wallContacts.validate(domain.walls.size());
    materials.validate();
    if (!materials.species.empty()) {
      for (std::size_t k = 0; k < n; ++k) {
        if (species[k] < 0 || static_cast<std::size_t>(species[k]) >= materials.species.size()) {
          throw Error("particle " + std::to_string(id[k]) + " has species " + std::to_string(species[k]) + ", but the "
                      "materials name " + std::to_string(materials.species.size()) + " species");
        }
      }
    }
    for (const auto& w : materials.walls) {
      if (static_cast<std::size_t>(w.wall) >= domain.walls.size()) {
        throw Error("materials name wall " + std::to_string(w.wall) + " of " + std::to_string(domain.walls.size()));
      }
    }
  } catch (const Error& e) {
    throw e.withContext("particle frame at step " + std::to_string(step));
  }
}

}  // namespace grainbridge::core::data
