#pragma once
// How a phase of a mixture counts contacts in its kinetic theory under Lebowitz's g0: the g0_mm and
// the two sums of KineticState (contactSum, dissipationSum) that Lun1984 reads, by either form:
// Summed, MFiX's form since 2005 (SUM_EpsGo, KineticState.hpp): eps_s g0 becomes sum_l eps_l g0_ml
// in the pressure, viscosities and conductivity and sum_l eps_l g0_ll in the dissipation, so two
// identical phases add up to one; PerPhase, the equations as printed (Eqs. 3.21-3.25, 5.7, 5.20)
// and as MFiX ran them before 2005-06: each phase's own eps_sm g0_mm throughout, so a phase
// collides with its own kind only (two identical halves of a bed dissipate half as much).
// The multi-fluid model and the mixture closures' comparison (issue 60) share it.
#include <cstddef>
#include <span>

#include "engines/closures/KineticState.hpp"
#include "engines/closures/RadialDistribution.hpp"

namespace grainbridge::closures {

enum class MixtureKineticTheory { Summed, PerPhase };

// Sets state.g0, contactSum and dissipationSum of phase `own` of the mixture whose fractions are
// `fractions` (the mixture's g0 made from the same fractions). Inline: the multi-fluid model asks
// for it three times per phase, cell and outer iteration.
inline void setMixtureContacts(const LebowitzMixture& mixture, std::span<const double> fractions, std::size_t own,
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
