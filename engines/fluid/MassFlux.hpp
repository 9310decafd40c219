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

// F [kg/s] on every face of each active axis, positive along the axis; zero on wall faces.
[[nodiscard]] std::array<FaceField, 3> massFluxes(const PhaseFields& phase, const CellField& density,
                                                  const Boundaries& boundaries);

}  // namespace grainbridge::fluid
