#pragma once
// The minimum fluidization velocity a gas-solids drag law implies: the superficial velocity U at
// which the drag on a packed bed of void fraction eps_g carries its buoyant weight. From the
// steady momentum balances of Eqs. 3.3-3.4 with the solids at rest and the gas at U / eps_g,
//   beta(eps_g, U / eps_g) U = eps_s eps_g^2 (rho_s - rho_g) g,
// solved for U by bisection (beta U grows with U). VALIDATION.md quotes these numbers for the
// Goldschmidt bed (1.21 m/s for Syamlal-O'Brien C 0.8 D 2.65, 2.49 mm, eps 0.417) and the grain
// bed's fluidization points (about 0.80, 0.70, 0.64 m/s for Table 4.3's sets).
#include "engines/closures/GasSolidsDrag.hpp"

namespace grainbridge::closures {

struct PackedBed {
  double voidFraction = 0.4;     // eps_g [-]
  double diameter = 0.0;         // d_p [m]
  double solidsDensity = 0.0;    // rho_s [kg/m^3]
  double gasDensity = 1.2;       // rho_g [kg/m^3]
  double gasViscosity = 1.8e-5;  // mu_g [Pa s]
  double gravity = 9.81;         // |g| [m/s^2]
};

// U_mf [m/s]; throws grainbridge::Error when the law does not carry the bed below 1e3 m/s.
[[nodiscard]] double minimumFluidizationVelocity(const GasSolidsDrag& drag, const PackedBed& bed);

}  // namespace grainbridge::closures
