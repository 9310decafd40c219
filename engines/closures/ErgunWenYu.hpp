#pragma once
// Ergun / Wen-Yu gas-solids drag (Ergun 1952 for dense beds, Wen and Yu 1966 for dilute ones),
// as the reference prints it for TF-DEM (Eqs. 7.30-7.31, after Tsuji et al. 1993), and in
// Gidaspow's published form (Gidaspow 1994, Multiphase Flow and Fluidization, Eqs. 5.21-5.23;
// MFIX's DRAG_TYPE GIDASPOW) as a named variant:
//
//   beta = 150 eps_s^2 mu_g / (eps_g d^2) + 1.75 eps_s rho_g |v_g - v_s| / d      eps_g <= 0.8
//        = 3/4 C_D eps_g eps_s rho_g |v_g - v_s| / d  eps_g^n                     eps_g >  0.8  (7.30)
//   C_D  = 24 (1 + 0.15 Re^0.687) / Re   for Re < 1000,   C_D,Newton above           (7.31)
//   Re   = d eps_g |v_g - v_s| rho_g / mu_g
//
// As printed (`ergun_wen_yu`, the TF-DEM default): n = -2.7, C_D,Newton = 0.43. Gidaspow
// (`gidaspow`): n = -2.65, C_D,Newton = 0.44. Neither law is continuous: beta jumps at
// eps_g = 0.8 (Ergun against Wen-Yu, by construction) and C_D at Re = 1000 (0.4383 from the
// Schiller-Naumann branch against 0.43 or 0.44). A blended law would be another named variant.
#include <string_view>

#include "engines/closures/DragState.hpp"

namespace grainbridge::closures {

struct ErgunWenYu {
  struct Params {
    double voidageExponent = -2.7;        // n of Eq. 7.30 (Wen-Yu's -2.65 in Gidaspow's form)
    double newtonDragCoefficient = 0.43;  // C_D for Re >= 1000 in Eq. 7.31 (0.44 in Gidaspow's form)
  };
  // The law as Eqs. 7.30-7.31 print it.
  [[nodiscard]] static ErgunWenYu asPrinted() { return {}; }
  // Gidaspow's published form.
  [[nodiscard]] static ErgunWenYu gidaspow() { return {{-2.65, 0.44}}; }

  // The dense/dilute switch of Eq. 7.30 and the Reynolds number switch of Eq. 7.31.
  static constexpr double kErgunVoidFraction = 0.8;
  static constexpr double kNewtonReynolds = 1000.0;

  [[nodiscard]] static constexpr std::string_view name() { return "ergun_wen_yu"; }
  Params params;
  // Validates the state (validate(DragState)).
  [[nodiscard]] DragCoefficients evaluate(const DragState& state) const;
  // C_D of Eq. 7.31 at Reynolds number `re` (> 0).
  [[nodiscard]] double dragCoefficient(double re) const;
};

}  // namespace grainbridge::closures
