#include "core/data/WallContactList.hpp"

#include <string>

#include "core/Error.hpp"

namespace grainbridge::core::data {

namespace {
template <class T>
void checkLength(const std::vector<T>& v, const char* name, std::size_t expected) {
  if (v.size() != expected) {
    throw Error("wall contact array '" + std::string(name) + "' has " + std::to_string(v.size()) +
                " entries, expected " + std::to_string(expected) + " (the length of 'particle')");
  }
}
}  // namespace

void WallContactList::validate(std::size_t wallCount) const {
  const std::size_t m = particle.size();
  checkLength(wall, "wall", m);
  checkLength(point, "point", m);
  checkLength(forceNormal, "forceNormal", m);
  checkLength(forceTangential, "forceTangential", m);
  for (std::size_t c = 0; c < m; ++c) {
    if (wall[c] < 0 || static_cast<std::size_t>(wall[c]) >= wallCount) {
      throw Error("wall contact " + std::to_string(c) + " refers to wall " + std::to_string(wall[c]) +
                  ", but the domain has " + std::to_string(wallCount) + " wall(s)");
    }
  }
}

}  // namespace grainbridge::core::data
