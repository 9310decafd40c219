#pragma once
// Solids-solids drag between solids phases l and m (Syamlal 1987, the reference's Eq. 3.18;
// MFIX's model/drag_ss.f), the momentum exchange I_ml = -F_sml (v_sl - v_sm) of Eq. 3.17
// without its R_ml term:
//
//   F_sml = 3 (1 + e_lm)(pi/2 + C_f pi^2/8) eps_sl rho_sl eps_sm rho_sm (d_l + d_m)^2 g0_lm |v_sl - v_sm|
//           / (2 pi (rho_sl d_l^3 + rho_sm d_m^3))                                          (3.18)
//
// The reference gives neither C_f nor e_lm (VALIDATION.md). Chosen here:
//   - e_lm: the normal restitution between the two phases' particles; MFIX uses its particle
//     restitution C_E here (drag_ss.f), and with the rotation model on it stays e, not e_eff
//     (e_eff enters only Eqs. 5.20-5.21);
//   - C_f: the coefficient of friction between the two phases' particles (Syamlal 1987 derives
//     the pi^2/8 term from sliding collisions); default 0, the smooth-sphere value, so that a
//     config states its friction. The reference gives none and MFiX refuses two solids phases
//     without it: configs/goldschmidt-binary.json takes 0, its MFiX 2003-05 arm
//     (goldschmidt-binary-mfix2005.json) 0.1, about Table 5.1's particle friction (0.15 / 0.10).
// MFIX's extra C(10) P* term for two close-packed phases is not included.
#include <string_view>

namespace grainbridge::closures {

struct SolidsSolidsDrag {
  struct Params {
    double frictionCoefficient = 0.0;  // C_f [-], >= 0
    double restitution = 1.0;          // e_lm [-], in (0, 1]
  };
  struct Phase {
    double solidFraction = 0.0;  // eps_s [-], >= 0
    double density = 0.0;        // rho_s material density [kg/m^3], > 0
    double diameter = 0.0;       // d_p [m], > 0
  };

  [[nodiscard]] static constexpr std::string_view name() { return "solids_drag"; }
  Params params;
  // F_sml [kg/(m^3 s)] for radial distribution g0_lm (> 0) and relative speed |v_sl - v_sm|.
  // Throws grainbridge::Error naming a value out of range.
  [[nodiscard]] double evaluate(const Phase& l, const Phase& m, double g0, double relativeSpeed) const;
};

}  // namespace grainbridge::closures
