#pragma once
// Input and output of a gas-solids drag law for one solids phase m, in SI units. Every law
// (SyamlalOBrien, ErgunWenYu) maps a DragState to a DragCoefficients, so the multi-fluid engine
// (Eq. 3.3-3.4: I_gm = beta (v_s - v_g)), TF-DEM's cell-averaged drag (Eq. 7.33) and its
// per-particle drag (Eq. 7.29) call the same law.
namespace grainbridge::closures {

struct DragState {
  double voidFraction = 1.0;   // eps_g [-], 0 < eps_g <= 1
  double solidFraction = 0.0;  // eps_sm of this phase [-], >= 0 (eps_g + sum eps_s = 1)
  double diameter = 0.0;       // d_pm [m], > 0
  double gasDensity = 0.0;     // rho_g [kg/m^3], > 0
  double gasViscosity = 0.0;   // mu_g [Pa s], > 0
  double slip = 0.0;           // |v_g - v_sm| (or |v_g^i - v_pi| for one particle) [m/s], >= 0
};

struct DragCoefficients {
  // beta = F_gm of Eq. 3.10 / beta of Eq. 7.30: momentum exchange per unit volume and unit slip
  // [kg/(m^3 s)].
  double beta = 0.0;
  // The per-particle form of Eq. 7.29: f_d = particle (v_g - v_p) with
  // particle = pi d^3 beta / (6 eps_g eps_s) [kg/s], so that eps_g f_d summed over a cell's
  // particles and divided by its volume is beta (v_g - v_s) again (Eqs. 7.32-7.33). Finite as
  // eps_s -> 0 (a lone particle), where beta itself vanishes.
  double particle = 0.0;
};

// Throws grainbridge::Error naming the first quantity out of range and its value (NaN included).
void validate(const DragState& state);

// beta / eps_s of a law -> both coefficients: beta = eps_s (beta / eps_s), and the per-particle
// form pi d^3 (beta / eps_s) / (6 eps_g), so neither divides by a vanishing eps_s.
[[nodiscard]] DragCoefficients dragFromBetaPerSolidFraction(const DragState& state, double betaPerSolidFraction);

}  // namespace grainbridge::closures
