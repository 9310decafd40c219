#include "engines/dem/contact/ContactModels.hpp"

namespace grainbridge::dem::contact {

namespace {
template <class Law>
bool chosen(const ContactChoice& c) {
  return c.normal == Law::Normal::name && c.damping == Law::Damping::name && c.tangential == Law::Tangential::name;
}
template <class... Laws>
std::optional<AnyContactLaw> find(TypeList<Laws...> /*laws*/, const ContactChoice& choice) {
  std::optional<AnyContactLaw> out;
  ((chosen<Laws>(choice) ? (out = Laws{}, true) : false) || ...);
  return out;
}
}  // namespace

std::optional<AnyContactLaw> findContactLaw(const ContactChoice& choice) { return find(ContactLaws{}, choice); }

}  // namespace grainbridge::dem::contact
