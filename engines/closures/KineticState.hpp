#pragma once
// Input and output of a kinetic-theory (KTGF) closure for one solids phase, in SI units; a phase
// of a mixture carries the mixture's contact sums (below). Every model (Lun1984,
// SyamlalAlgebraic) maps a KineticState to a KineticTransport, so the compare stage can put
// DEM-extracted values and each model's prediction side by side.
namespace grainbridge::closures {

struct KineticState {
  double solidFraction = 0.0;        // eps_s [-], 0 <= eps_s < 1
  double granularTemperature = 0.0;  // theta = <C^2>/3 (Eq. 5.6) [m^2/s^2], >= 0
  double diameter = 0.0;             // d_p [m], > 0
  double density = 0.0;              // rho_s, material density of a grain [kg/m^3], > 0
  double restitution = 1.0;          // e, normal restitution between grains [-], 0 < e <= 1
  // beta, the gas-solids drag coefficient of the momentum exchange I_gm = beta (v_g - v_s)
  // [kg/(m^3 s)] (MFIX F_gs). Only Lun1984 reads it (Ma-Ahmadi modification); 0 for a granular
  // flow without interstitial gas, such as the DEM shear cells the compare stage checks.
  double gasDragCoefficient = 0.0;
  // A phase of a mixture, or one phase with another radial distribution than Carnahan-Starling:
  // g0_mm at contact with its own kind, and over every solids phase l the sums MFIX writes
  // SUM_EpsGo (calc_mu_s.f and source_granular_energy.f, 2005): sum_l eps_l g0_ml, which replaces
  // eps_s g0 in the pressure, viscosities and conductivity, and sum_l eps_l g0_ll, which replaces
  // it in the collisional dissipation. Then two identical phases add up to the one phase (their
  // stresses and dissipation are additive). g0 = 0: one phase, Carnahan-Starling g0 of
  // solidFraction, both sums eps_s g0. Only Lun1984 reads the sums; SyamlalAlgebraic reads g0.
  double g0 = 0.0;
  double contactSum = 0.0;
  double dissipationSum = 0.0;
};

struct KineticTransport {
  double pressure = 0.0;        // p_s [Pa]
  double shearViscosity = 0.0;  // mu_s [Pa s]
  // xi_s [Pa s], the true bulk viscosity: tau_s = 2 mu_s (D - tr(D) I / 3) + xi_s tr(D) I.
  double bulkViscosity = 0.0;
  double conductivity = 0.0;     // kappa_s [kg/(m s)]: granular energy flux q = -kappa_s grad(theta)
  double dissipationRate = 0.0;  // collisional dissipation J_coll, Eq. 5.7 [W/m^3]

  // lambda_s of Eq. 3.22, tau_s = 2 mu_s D + lambda_s tr(D) I (MFIX's "second viscosity"
  // LAMBDA_s): lambda_s = xi_s - 2 mu_s / 3, so it can be negative.
  [[nodiscard]] double secondViscosity() const { return bulkViscosity - 2.0 / 3.0 * shearViscosity; }
};

// g0 at contact of the state's phase with its own kind: the given g0, or Carnahan-Starling's of
// solidFraction when none is given.
[[nodiscard]] double contactG0(const KineticState& state);

// Throws grainbridge::Error naming the first quantity out of range and its value (NaN included):
// solid fraction outside [0, 1), negative granular temperature, diameter or density not
// positive, restitution outside (0, 1], negative gas drag coefficient; a given g0 not finite and
// positive, or its sums negative.
void validate(const KineticState& state);

}  // namespace grainbridge::closures
