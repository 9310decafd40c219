#pragma once
// The gas-solids drag F_gm (v_s - v_g) of Eqs. 3.3-3.4 on one velocity component, added to the
// momentum systems of every phase by the partial elimination of Syamlal (1998), which the
// reference uses (Section 3.3.2): on each face the point-coupled pair
//   (a_g + sum_m F_m dV) u_g = H_g + sum_m F_m dV u_m,   (a_m + F_m dV) u_m = H_m + F_m dV u_g
// (H the neighbour sum plus b) is solved for each phase's own velocity with the other phases'
// H at the current iterate, so a phase sees the drag implicitly: with F dt / rho >> 1 the two
// phases move together at once instead of over many outer iterations.
// Both phases see one face value of F_gm, the mean of its two cells (computed once here): were
// the gas and the solids to interpolate it differently, the momentum they exchange would not
// balance and SIMPLE stalls.
// The same point-coupled matrix gives the velocity corrections: u'_m = -d_m (P'_E - P'_P) for the
// gas pressure (every phase feels -eps_m grad P_g) and u'_m = -e_m (P_s'_E - P_s'_P) for a solids
// pressure change, so the pressure and fraction corrections carry the eliminated drag.
#include <array>
#include <cstddef>
#include <vector>

#include "engines/fluid/FlowState.hpp"
#include "engines/fluid/PhaseProperties.hpp"
#include "engines/fluid/StencilSystem.hpp"

namespace grainbridge::fluid {

// Per phase, the coefficients of one axis's faces: u'_m = -pressure[m] (P'_E - P'_P) [m/(s Pa)],
// and for a solids phase u'_m = -solidsPressure[m] (P_s'_E - P_s'_P) with only phase m's solids
// pressure changing.
struct CorrectionCoefficients {
  std::vector<FaceField> pressure;
  std::vector<FaceField> solidsPressure;
};

// Adds the drag to `systems` (one per phase, all of component `axis`, assembled without it),
// relaxes each by `relaxation` (StencilSystem::relax), and returns the correction coefficients.
// A dilute solids face (Momentum.hpp) keeps its own equation: the gas sees its drag explicitly,
// and its corrections are zero. A given phase (given[m] != 0; `given` empty: none, FlowModel::givenPhase; its system
// is left alone) is dilute on every face, except that its exchange stays in the other phases'
// correction coefficients: their velocities feel it implicitly while its own cannot change, so
// the gas pressure correction is d_g = eps_g A / (a_g / alpha + F_gm dV).
CorrectionCoefficients coupleAndRelax(std::vector<StencilSystem>& systems, const FlowState& state,
                                      const FlowProperties& properties, int axis, double relaxation,
                                      double diluteFraction, const std::vector<char>& given = {});

}  // namespace grainbridge::fluid
