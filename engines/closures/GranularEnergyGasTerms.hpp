#pragma once
// The gas terms of the granular-energy equation (Eq. 5.5): production by gas-particle slip,
// gamma_slip, and viscous damping by the gas, J_vis. The reference defines neither
// (VALIDATION.md); these are the forms of MFIX's Lun path (source_granular_energy in
// model/source_granular_energy.f, after Koch 1990 and Gidaspow 1994):
//
//   gamma_slip = 81 eps_s (mu_g |v_g - v_s|)^2 / (g0 d^3 rho_s sqrt(pi theta))
//   J_vis      = 3 beta theta          (Chapter 3's Phi_gm = -3 F_gm theta, line ~468)
//
// Both are returned as coefficients of the temperature, gamma_slip = a / sqrt(theta) and
// J_vis = b theta, so an engine treats them implicitly in theta (J_vis) or evaluates a at its
// floor temperature (gamma_slip diverges as theta -> 0 and must never be evaluated there).
#include <string_view>

namespace grainbridge::closures {

struct GranularEnergyGasTerms {
  struct State {
    double solidFraction = 0.0;       // eps_s [-]
    double diameter = 0.0;            // d [m]
    double density = 0.0;             // rho_s [kg/m^3]
    double radialDistribution = 1.0;  // g0 [-]
    double gasViscosity = 0.0;        // mu_g [Pa s]
    double slip = 0.0;                // |v_g - v_s| [m/s]
    double beta = 0.0;                // gas-solids drag coefficient [kg/(m^3 s)]
  };
  struct Result {
    double slipProductionCoefficient = 0.0;                   // a [W/m^3 (m/s)]: gamma_slip = a / sqrt(theta)
    double viscousDissipationCoefficient = 0.0;               // b [kg/(m^3 s)]: J_vis = b theta
    [[nodiscard]] double slipProduction(double theta) const;  // gamma_slip at theta > 0 [W/m^3]
    [[nodiscard]] double viscousDissipation(double theta) const { return viscousDissipationCoefficient * theta; }
  };

  [[nodiscard]] static constexpr std::string_view name() { return "granular_energy_gas_terms"; }
  // Throws grainbridge::Error naming an input out of range.
  [[nodiscard]] Result evaluate(const State& state) const;
};

}  // namespace grainbridge::closures
