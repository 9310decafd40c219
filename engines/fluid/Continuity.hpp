#pragma once
// The continuity equations (Eqs. 3.1-3.2, no interphase mass transfer) and the two corrections
// of the modified SIMPLE method (Section 3.3.3) built on them.
//
// Mass imbalance of phase m in cell P, first-order implicit in time (Eq. 3.61):
//   R_m = (rho_m eps_m - rho_m^0 eps_m^0) dV / dt + sum_faces F_out - F_in
//
// Gas pressure correction: the gas continuity with u'_g = -d_g (P'_E - P'_P) on every face
// (d_g from InterphaseCoupling, so it carries the drag the solids exert) gives
//   a_P P'_P = sum a_nb P'_nb - R_g,   a_nb = rho_g eps_g A d_g on the face to nb,
// with P' = 0 in the ghosts of pressure outlets. A domain with no outlet fixes P' = 0 in its
// first cell (its pressure level is free; the equations of the other cells fix the rest).
//
// Solids fraction correction (instead of a solids pressure correction, which needs dP_s/deps_s
// away from zero as eps_s -> 0): with eps_s = eps_s* + eps_s' (Eq. 3.69) and the velocity
// correction u'_s = -e_s (dP_s/deps_s) (eps_s'_E - eps_s'_P), the linearised solids continuity
//   rho_s dV/dt eps'_P + sum_faces rho_s A (u*_s eps'_upwind - eps*_s,f u'_s) = -R_s
// is an upwind convection-diffusion equation for eps_s'; the plastic pressure's steep slope
// enters through dP_s/deps_s here, implicitly, and never as an explicit force alone.
#include <array>
#include <cstddef>
#include <vector>

#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/FlowState.hpp"
#include "engines/fluid/PhaseProperties.hpp"
#include "engines/fluid/StencilSystem.hpp"

namespace grainbridge::fluid {

// R_m at cell c [kg/s], from the phase's face fluxes (MassFlux.hpp), its density now and at the
// last time level. dt = 0: steady, no transient.
[[nodiscard]] double massImbalance(const CellField& fraction, const CellField& oldFraction, const CellField& density,
                                   const CellField& oldDensity, const std::array<FaceField, 3>& flux, double dt,
                                   std::size_t c);

// The gas pressure correction system; `d` the gas's pressure coefficients per axis. A
// compressible gas adds eps_g dV/dt d rho/dP to a_P (its density follows the pressure), and
// then the pressure level is fixed by the mass in the domain, outlet or not.
[[nodiscard]] StencilSystem assemblePressureCorrection(const FlowState& state, const FlowState& old,
                                                       const FlowProperties& properties,
                                                       const FlowProperties& oldProperties,
                                                       const Boundaries& boundaries,
                                                       const std::array<FaceField, 3>& gasFlux,
                                                       const std::array<const FaceField*, 3>& d, double dt);

// The fraction correction system of solids phase m; `e` its solids-pressure coefficients per axis.
[[nodiscard]] StencilSystem assembleFractionCorrection(const FlowState& state, const FlowState& old,
                                                       const FlowProperties& properties,
                                                       const FlowProperties& oldProperties, std::size_t m,
                                                       const std::array<FaceField, 3>& flux,
                                                       const std::array<const FaceField*, 3>& e, double dt);

// Phase m's continuity solved once more, implicitly, with the step's converged faces: each face's
// flux |F| = c_f eps_upwind, c_f = |F| / eps*_upwind from the converged iterate eps* (rho A |v|
// where eps*_upwind <= 0), so
//   rho_P dV/dt eps_P + sum_out c_f eps_P - sum_in c_f eps_nb = rho_P^0 eps_P^0 dV/dt.
// The matrix is an M-matrix (column sums rho dV/dt > 0), so eps >= 0 wherever eps^0 >= 0 and
// the inflowing ghosts are >= 0; the faces telescope, so the phase's mass balance is exact. At a
// converged iterate eps = eps* up to the step's continuity residual, which this removes: the
// SIMPLE loop meets each cell's continuity to the tolerance only, and a thin cell the solids
// are leaving would otherwise end the step a residual below zero. Overwrites the interior of
// `phase.fraction`; `flux` are massFluxes of the phase at eps*. Transient steps only (dt > 0).
// Returns the fluxes it moved mass with, c_f eps_upwind at the solved eps (what crossed each face
// over the step, BoundaryFlow.hpp), zero on closed faces.
//
// `how` other than Direct (Gauss-Seidel: its sweeps keep an M-matrix's iterate >= 0) solves to a
// tolerance and then finishes in flux form: the fluxes are c_f eps*_upwind at the iterate eps*,
// and each cell takes eps = eps* + r / (rho dV/dt), what its old mass and those fluxes leave
// (r its residual), so the faces telescope and the balance is exact to round-off whatever the
// tolerance. A cell that ends a round-off below zero is set to zero if the mass that drops is
// within 1e-15 of the phase's (measured: 1e-20 of a cell's fraction in the combine's front);
// beyond that, the direct solve instead.
[[nodiscard]] std::array<FaceField, 3> solveFractionNonNegative(PhaseFields& phase, const CellField& oldFraction, const CellField& density,
                                                         const CellField& oldDensity,
                                                         const std::array<FaceField, 3>& flux,
                                                         const Boundaries& boundaries, double dt,
                                                         const LinearSolve& how = {});

}  // namespace grainbridge::fluid
