#pragma once
// The registered contact sub-models and every composition of them. Adding a sub-model is one
// struct (beside its kind's others) plus one line in its list below; the engine, the stage's
// options and the generic contact tests pick it up from here (docs/adding-a-contact-law.md).
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "engines/dem/contact/ContactLaw.hpp"
#include "engines/dem/contact/DampingModels.hpp"
#include "engines/dem/contact/NormalModels.hpp"
#include "engines/dem/contact/TangentialModels.hpp"

namespace grainbridge::dem::contact {

template <class... T>
struct TypeList {};

// ---- the registry: one line per sub-model -----------------------------------------------------
using NormalModels = TypeList<LinearSpring,  //
                              HertzSpring>;
using DampingModels = TypeList<MassScaledDamping,  //
                               DimensionalDamping>;
using TangentialModels = TypeList<ProjectedHistory,  //
                                  LammpsHistory>;
// ------------------------------------------------------------------------------------------------

// The sub-models a run uses, by name (the dem stage's normal_model, damping_model and
// tangential_model); the defaults are the reference's Eqs. 6.4-6.6 with a linear spring.
struct ContactChoice {
  std::string normal = LinearSpring::name;
  std::string damping = MassScaledDamping::name;
  std::string tangential = ProjectedHistory::name;
  friend bool operator==(const ContactChoice&, const ContactChoice&) = default;
};

namespace detail {
template <class... Lists>
struct Concat;
template <class... A>
struct Concat<TypeList<A...>> {
  using type = TypeList<A...>;
};
template <class... A, class... B, class... Rest>
struct Concat<TypeList<A...>, TypeList<B...>, Rest...> {
  using type = typename Concat<TypeList<A..., B...>, Rest...>::type;
};
template <class N, class D, class Ts>
struct WithTangential;
template <class N, class D, class... Ts>
struct WithTangential<N, D, TypeList<Ts...>> {
  using type = TypeList<ContactLaw<N, D, Ts>...>;
};
template <class N, class Ds, class Ts>
struct WithDamping;
template <class N, class... Ds, class Ts>
struct WithDamping<N, TypeList<Ds...>, Ts> {
  using type = typename Concat<typename WithTangential<N, Ds, Ts>::type...>::type;
};
template <class Ns, class Ds, class Ts>
struct AllCompositions;
template <class... Ns, class Ds, class Ts>
struct AllCompositions<TypeList<Ns...>, Ds, Ts> {
  using type = typename Concat<typename WithDamping<Ns, Ds, Ts>::type...>::type;
};
template <class List>
struct VariantOf;
template <class... L>
struct VariantOf<TypeList<L...>> {
  using type = std::variant<L...>;
};
template <class... M>
std::vector<std::string> namesOf(TypeList<M...> /*list*/) {
  return {M::name...};
}
}  // namespace detail

// Every composition, as one list and as the variant the engine visits once per force evaluation.
using ContactLaws = typename detail::AllCompositions<NormalModels, DampingModels, TangentialModels>::type;
using AnyContactLaw = typename detail::VariantOf<ContactLaws>::type;

inline std::vector<std::string> normalModelNames() { return detail::namesOf(NormalModels{}); }
inline std::vector<std::string> dampingModelNames() { return detail::namesOf(DampingModels{}); }
inline std::vector<std::string> tangentialModelNames() { return detail::namesOf(TangentialModels{}); }

// The composition these names choose; nullopt when one of them is not registered.
std::optional<AnyContactLaw> findContactLaw(const ContactChoice& choice);

}  // namespace grainbridge::dem::contact
