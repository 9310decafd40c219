#include "engines/closures/MixtureContacts.hpp"

namespace grainbridge::closures {

void setMixtureContacts(const LebowitzMixture& mixture, std::span<const double> fractions, std::size_t own,
                        MixtureKineticTheory form, KineticState& state) {
  state.g0 = mixture.g0(own, own);
  if (form == MixtureKineticTheory::PerPhase) {
    // Eqs. 3.21-3.25, 5.7 and 5.20 as printed: eps_sm g0_mm, the phase's own contacts.
    state.contactSum = fractions[own] * state.g0;
    state.dissipationSum = state.contactSum;
    return;
  }
  state.contactSum = 0.0;
  state.dissipationSum = 0.0;
  for (std::size_t l = 0; l < fractions.size(); ++l) {
    state.contactSum += fractions[l] * mixture.g0(own, l);
    state.dissipationSum += fractions[l] * mixture.g0(l, l);
  }
}

}  // namespace grainbridge::closures
