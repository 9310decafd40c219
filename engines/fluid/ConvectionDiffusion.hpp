#pragma once
// The scalar transport equation of Section 3.3.2.1 (Eq. 3.56) for a cell-centred Phi, steady,
// with given face velocities:
//   div(rho v Phi) = div(Gamma grad Phi) + S
// integrated over each cell (Eq. 3.58) with the central diffusive flux of Eq. 3.59 and the
// superbee convective face value of Eq. 3.60 by deferred correction: the matrix carries
// first-order upwind (a_nb = D + max(-+F, 0), always diagonally dominant), and the difference
// between the superbee and the upwind face values, from the current iterate, enters the source
// b. At convergence the solution is the superbee one. A face whose far-upwind cell lies beyond
// the ghost layer takes the upwind value.
#include <array>

#include "engines/fluid/Fields.hpp"
#include "engines/fluid/StencilSystem.hpp"

namespace grainbridge::fluid {

struct ConvectionDiffusion {
  double density = 1.0;      // rho
  double diffusivity = 0.0;  // Gamma
  double source = 0.0;       // S per unit volume
  // Face velocities per active axis (their faces' normal components).
  std::array<const FaceField*, 3> velocity{nullptr, nullptr, nullptr};
};

// Assembles the upwind matrix and the superbee deferred correction at the iterate `phi` into a
// fresh system (interior cells active).
StencilSystem assembleConvectionDiffusion(const ConvectionDiffusion& equation, const CellField& phi);

}  // namespace grainbridge::fluid
