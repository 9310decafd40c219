#pragma once
// The closure catalog's entries for the gas-solids drag laws, made from each law's own
// declarations (engines/closures/DragLawTraits.hpp): name, doc, equations, source, parameters
// and their check. Templated on the list so that the catalog (DragLaws) and a test with one more
// law (tests/workflows/DragLawWiringTest.cpp) go through the same code.
#include <nlohmann/json.hpp>
#include <vector>

#include "engines/closures/GasSolidsDrag.hpp"
#include "workflows/closures/ClosureCatalog.hpp"

namespace grainbridge::workflows::closures {

// The state every drag law is evaluated at (eps_g, eps_s, d_p, rho_g, mu_g, |v_g - v_s|), and
// its reading and the outputs (beta, the per-particle coefficient).
std::shared_ptr<params::ParamSchema> dragInputs();
grainbridge::closures::DragState dragState(const nlohmann::json& inputs);
std::vector<ClosureOutput> dragOutputs(const grainbridge::closures::DragCoefficients& c);

// Parameter `p` of Law as a schema entry: the default is the law's, `positive` its range.
template <class Law>
params::ParamSpec dragParameterSpec(const grainbridge::closures::DragParameter<typename Law::Params>& p) {
  auto spec = params::ParamSpec::number(p.key).defaultValue(Law{}.params.*p.member);
  if (p.positive) spec.positive();
  return std::move(spec.doc(p.doc));
}

// Law with the resolved (catalog-named) parameters `params`.
template <class Law>
Law dragLawWith(const nlohmann::json& params) {
  Law law;
  for (const auto& p : Law::parameters) law.params.*p.member = params.at(p.key).template get<double>();
  return law;
}

template <class Law>
ClosureEntry dragLawEntry() {
  auto p = std::make_shared<params::ParamSchema>();
  for (const auto& parameter : Law::parameters) p->add(dragParameterSpec<Law>(parameter));
  ClosureEntry entry{Law::name,
                     Law::doc,
                     Law::equations,
                     Law::source,
                     p,
                     dragInputs(),
                     [](const nlohmann::json& params, const nlohmann::json& in) {
                       return dragOutputs(dragLawWith<Law>(params).evaluate(dragState(in)));
                     }};
  entry.checkParams = [](const nlohmann::json& params) {
    return grainbridge::closures::paramsProblem<Law>(dragLawWith<Law>(params).params).why;
  };
  return entry;
}

// One entry per law of the list, in its order.
template <class... L>
std::vector<ClosureEntry> dragLawEntries(grainbridge::closures::TypeList<L...> /*laws*/) {
  return {dragLawEntry<L>()...};
}

}  // namespace grainbridge::workflows::closures
