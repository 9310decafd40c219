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
  } catch (const Error& e) {
    throw e.withContext("particle frame at step " + std::to_string(step));
  }
}

}  // namespace grainbridge::core::data
