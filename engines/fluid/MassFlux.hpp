#pragma once
// The convective mass flux of a phase through each face, F = rho_m eps_m v_m A (the flux of
// Eqs. 3.1-3.2 integrated over a face): rho upwind, eps_m at the face by superbee (Eq. 3.60) from
// the current iterate, so the continuity equations, the fraction correction and the momentum
// equations' convection all move mass with the same face values.
#include <array>
#include <cstddef>

#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/Fields.hpp"

namespace grainbridge::fluid {

// The face value of eps_m on the face (axis, face), for the velocity `u` on it.
[[nodiscard]] double faceFraction(const CellField& fraction, int axis, std::size_t face, double u);

// What a solids phase's face values may carry out of each cell over a step: the fraction at the
// step's start and the step. Without it (the gas) the face values are superbee's.
struct OutflowBudget {
  const CellField* start = nullptr;
  double dt = 0.0;
};

// F [kg/s] on every face of each active axis, positive along the axis; zero on wall faces.
// With a budget the faces stay positivity-preserving: superbee's face value is the upwind cell's
// value plus an antidiffusive part, and where the antidiffusive outflows of an interior cell,
// sum |v| A (eps_f - eps_c) dt, would exceed what the cell held at the step's start, eps_c^n V,
// they are scaled down to it (Zalesak's limiting of the outflows alone). The upwind part is
// implicit and keeps the fraction non-negative by itself (an M-matrix), so then no face carries
// more out of a cell than the cell holds over the step.
// `m` is the phase's index (0 the gas): where a solids phase flows back in through a pressure
// outlet its face carries the patch's backflow fraction (the ghost repeats the interior, Boundaries).
[[nodiscard]] std::array<FaceField, 3> massFluxes(const PhaseFields& phase, const CellField& density,
                                                  const Boundaries& boundaries, const OutflowBudget& budget = {},
                                                  std::size_t m = 0);

}  // namespace grainbridge::fluid
