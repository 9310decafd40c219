#pragma once
// The granular-energy equation of one solids phase, Eq. 3.34 (Eq. 5.5 prints S:grad v with the
// opposite sign, a slip; VALIDATION.md), on the cells of the staggered grid:
//
//   3/2 [d(eps rho theta)/dt + div(eps rho theta v)] = S:grad v - div q + gamma_slip - J_coll - J_vis
//
// discretised like every transport equation here (Eq. 3.64): first-order implicit in time with
// the discretised continuity subtracted (as the momentum equations), convection upwind in the
// matrix with superbee by deferred correction, conduction q = -kappa grad(theta) central with the
// harmonic mean of kappa on each face (no conduction into a cell without solids).
//
// The model hands over each cell's sources split by sign, so that theta stays non-negative: what
// produces energy (tau:grad v, gamma_slip, -P div v where the solids are compressed) is `source`
// in b; what removes it in proportion to theta (J_coll = K theta^(3/2) linearised as
// K sqrt(theta*) theta, J_vis = 3 beta theta, P div v where they expand) is `sink` on the
// diagonal. With non-negative neighbour coefficients the solution of such a system is
// non-negative; a negative b left by the deferred correction is moved onto the diagonal
// (Patankar's rule for a negative source), so the bound also holds with superbee.
//
// Walls: nothing conducts through a wall face; a wall that the model gives a Johnson-Jackson
// energy flux (Eq. 5.9, 5.21 with rotation) adds its production c |v_slip|^2 to b and its
// dissipation, linear in theta at the iterate, to the diagonal, per unit wall area. Inlets and
// outlets: the ghost repeats the interior (Boundaries::apply), so only convection crosses them.
// A cell below the dilute fraction has no meaningful balance (every term vanishes with eps_s):
// there theta is the mean of its neighbours that hold solids, which carries the bed's values one
// cell into the freeboard, and zero beyond. A pinned cell (MFIX's plastic cells) has the row
// theta = pinnedTheta; its neighbours see it as a known value.
#include <array>
#include <cstddef>
#include <vector>

#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/FlowState.hpp"
#include "engines/fluid/PhaseProperties.hpp"
#include "engines/fluid/StencilSystem.hpp"

namespace grainbridge::mfm {

// Per interior cell of one solids phase, from the model at the current iterate.
struct GranularEnergyTerms {
  explicit GranularEnergyTerms(const fluid::StaggeredGrid& grid)
      : conductivity(grid),
        source(grid),
        sink(grid),
        wallProduction{fluid::CellField(grid), fluid::CellField(grid), fluid::CellField(grid)},
        wallSink{fluid::CellField(grid), fluid::CellField(grid), fluid::CellField(grid)},
        pinned(grid.paddedCount(), 0) {}
  fluid::CellField conductivity;  // kappa_s [kg/(m s)]
  fluid::CellField source;        // energy produced [W/m^3], >= 0
  fluid::CellField sink;          // energy removed per unit theta [kg/(m^3 s)], >= 0
  // Johnson-Jackson walls, per axis normal to the wall, held in the cell next to it: production
  // [W/m^2] and dissipation per unit theta [kg/(m^2 s)]; zero: adiabatic.
  std::array<fluid::CellField, 3> wallProduction;
  std::array<fluid::CellField, 3> wallSink;
  // Cells whose theta is held at pinnedTheta instead of solved for (MultiFluidParams::plasticTheta).
  std::vector<unsigned char> pinned;
  double pinnedTheta = 0.0;
};

struct GranularEnergyInputs {
  const fluid::FlowState* state = nullptr;  // the iterate (velocities, fractions, theta)
  const fluid::FlowState* old = nullptr;    // the last time level
  const fluid::CellField* oldDensity = nullptr;  // rho_s at the last time level
  const fluid::Boundaries* boundaries = nullptr;
  double dt = 0.0;               // [s]; 0: steady
  double diluteFraction = 1e-4;  // cells below it take the mean of their neighbours
};

// The system for theta of solids phase `m` (interior cells active; ghosts known).
[[nodiscard]] fluid::StencilSystem assembleGranularEnergy(const GranularEnergyInputs& in, std::size_t m,
                                                          const std::array<fluid::FaceField, 3>& massFlux,
                                                          const GranularEnergyTerms& terms);

}  // namespace grainbridge::mfm
