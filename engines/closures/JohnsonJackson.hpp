#pragma once
// Johnson and Jackson's (1987, J. Fluid Mech. 176:67-93) partial-slip wall for a solids phase,
// Eqs. 5.8-5.10 (and 5.21 with the rotation model), in the form a staggered-grid engine applies
// as Robin conditions on its ghost cells:
//
//   v_slip . S . n + sqrt(3) pi / (6 eps_max) phi' rho_s eps_s g0 theta^(1/2) |v_slip|^2 = 0      (5.8)
//   -n . q = sqrt(3) pi / (4 eps_max) (1 - e_w^2) eps_s rho_s g0 theta^(3/2) + v_slip . S . n      (5.9)
//   v_slip = v_s - v_w                                                                            (5.10)
//
// So the wall takes the tangential traction -c v_slip with c = sqrt(3) pi phi' rho_s eps_s g0
// sqrt(theta) / (6 eps_max) (a solids shear viscosity mu_s turns it into
// mu_s dv/dn = -c v_slip at the wall), and the granular energy balance at the wall is a
// production c |v_slip|^2 by slip against a dissipation by inelastic wall collisions. With the
// rotation model the dissipation's (1 - e_w^2) becomes (1 + e_w)(1 - e_w,eff) (Eq. 5.21).
// The reference gives neither the specularity phi' nor eps_max (VALIDATION.md): the MFiX run it
// lists used phi' = 0.6; eps_max is the solids fraction at packing, 1 - eps_g* in MFIX.
#include <optional>
#include <string_view>

namespace grainbridge::closures {

struct JohnsonJackson {
  struct Params {
    double specularity = 0.6;       // phi' in [0, 1]: 0 free slip, 1 all collisions diffuse
    double maxSolidFraction = 0.0;  // eps_s,max in (0, 1): required
    double wallRestitution = 1.0;   // e_w in (0, 1]
    // e_w,eff of the rotation model (EffectiveRestitution with the wall friction), or none.
    std::optional<double> wallEffectiveRestitution;
  };
  struct State {
    double solidFraction = 0.0;        // eps_s at the wall [-]
    double density = 0.0;              // rho_s [kg/m^3]
    double radialDistribution = 1.0;   // g0 [-]
    double granularTemperature = 0.0;  // theta [m^2/s^2]
    double slipSpeed = 0.0;            // |v_s - v_w| [m/s]
  };
  struct Result {
    double slipCoefficient = 0.0;  // c [kg/(m^2 s)]: wall traction -c v_slip
    double shearStress = 0.0;      // c |v_slip| [Pa], the magnitude of that traction
    double slipProduction = 0.0;   // c |v_slip|^2 [W/m^2], granular energy gained by slip
    double wallDissipation = 0.0;  // [W/m^2], lost in inelastic wall collisions
    // Into the flow through the wall: production - dissipation (= n . q with n out of the flow).
    [[nodiscard]] double energyFluxIntoFlow() const { return slipProduction - wallDissipation; }
  };

  [[nodiscard]] static constexpr std::string_view name() { return "johnson_jackson"; }
  Params params;
  // Throws grainbridge::Error naming a parameter or input out of range.
  [[nodiscard]] Result evaluate(const State& state) const;
};

}  // namespace grainbridge::closures
