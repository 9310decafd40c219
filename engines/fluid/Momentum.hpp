#pragma once
// The momentum equation of one phase (Eqs. 3.3-3.4) for the velocity component along `axis`,
// on the staggered control volume around each face (Section 3.3.2), in the form of Eq. 3.64:
//   transient   rho eps^0 dV / dt, first-order implicit (Eq. 3.61), with the discretised
//               continuity subtracted (Patankar), so a_P = sum a_nb + rho eps^0 dV / dt;
//   convection  first-order upwind in the matrix, superbee (Eq. 3.60) by deferred correction in
//               b; the control-volume face fluxes are averages of the phase's face mass fluxes;
//   viscous     div(mu grad u) implicit, central (Eq. 3.59); the rest of div(tau) (the transposed
//               gradient and lambda tr(D)) explicit in b, as MFiX does;
//   pressure    -eps_m grad P_g and, for solids, -grad P_s, explicit at the current iterate;
//   gravity     eps_m rho_m g;
//   source      the phase's explicit momentum source, if the model gives one (PhaseProperties).
// The interphase drag is not here: InterphaseCoupling adds it with partial elimination, after
// every phase is assembled. A solids face below the dilute threshold (MFiX DIL_EP_S) has no
// momentum equation worth the name (every coefficient vanishes with eps_s, and the ratios of
// vanishing terms blow up): as MFiX does, its velocity is the mean of the neighbouring faces'
// whose cells hold solids, or, with none, stays what it is; drag and corrections skip it.
#include <array>
#include <cstddef>
#include <vector>

#include "core/Types.hpp"
#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/FlowState.hpp"
#include "engines/fluid/PhaseProperties.hpp"
#include "engines/fluid/StencilSystem.hpp"

namespace grainbridge::fluid {

struct MomentumInputs {
  const FlowState* state = nullptr;  // the current iterate
  const FlowState* old = nullptr;    // the last time level
  const FlowProperties* properties = nullptr;
  const FlowProperties* oldProperties = nullptr;  // at the last time level (its density)
  const Boundaries* boundaries = nullptr;
  Vec3 gravity = Vec3::Zero();   // [m/s^2]
  double dt = 0.0;               // [s]; 0 for a steady solve (no transient term)
  double diluteFraction = 1e-4;  // solids faces below this eps_s keep only their local terms
};

// The system of phase `phase`, component `axis`, with the faces that carry unknowns active.
// `flux` are that phase's face mass fluxes (MassFlux.hpp) at the current iterate.
[[nodiscard]] StencilSystem assembleMomentum(const MomentumInputs& in, std::size_t phase, int axis,
                                             const std::array<FaceField, 3>& flux);

// Whether phase m's momentum on face (axis, face) is a dilute face's.
[[nodiscard]] bool diluteFace(const FlowState& state, std::size_t m, int axis, std::size_t face, double threshold);

// eps_m on a face, the mean of its two cells (the momentum control volume's fraction).
[[nodiscard]] inline double meanOnFace(const CellField& field, int axis, std::size_t face) {
  return 0.5 * (field[face] + field[field.grid().neighbour(face, axis, +1)]);
}

}  // namespace grainbridge::fluid
