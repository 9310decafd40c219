#include "core/data/ContactList.hpp"

#include <string>

#include "core/Error.hpp"

namespace grainbridge::core::data {

namespace {
template <class T>
void checkLength(const std::vector<T>& v, const char* name, std::size_t expected) {
  if (v.size() != expected) {
    throw Error("contact array '" + std::string(name) + "' has " + std::to_string(v.size()) + " entries, expected " +
                std::to_string(expected) + " (the length of 'i')");
  }
}
}  // namespace

void ContactList::validate() const {
  const std::size_t m = i.size();
  checkLength(j, "j", m);
  checkLength(branch, "branch", m);
  checkLength(contactPoint, "contactPoint", m);
  checkLength(forceNormal, "forceNormal", m);
  checkLength(forceTangential, "forceTangential", m);
  checkLength(forceNormalElastic, "forceNormalElastic", m);
  checkLength(forceNormalDissipative, "forceNormalDissipative", m);
  checkLength(forceTangentialElastic, "forceTangentialElastic", m);
  checkLength(forceTangentialDissipative, "forceTangentialDissipative", m);
}

}  // namespace grainbridge::core::data
