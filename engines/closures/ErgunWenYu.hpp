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
//
// ErgunWenYu is the shared code; the two named laws of GasSolidsDrag.hpp's list,
// ErgunWenYuAsPrinted and Gidaspow, are it with their own name, line of doc and defaults.
#include <array>

#include "engines/closures/DragLawTraits.hpp"
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

  // Shared by both named forms (their catalog entries cite the same sources).
  static constexpr const char* equations = "Eqs. 7.29-7.31, 7.33-7.34";
  static constexpr const char* source =
      "Ergun 1952, Wen and Yu 1966, Tsuji et al. 1993; Gidaspow 1994 (MFIX DRAG_TYPE GIDASPOW)";
  // Neither is a stage key: the stages run each form with its published constants.
  static constexpr std::array<DragParameter<Params>, 2> parameters{{
      {"voidage_exponent", &Params::voidageExponent, false, "n of eps_g^n in the Wen-Yu branch of Eq. 7.30"},
      {"newton_drag_coefficient", &Params::newtonDragCoefficient, true, "C_D above Re 1000 (Eq. 7.31)"},
  }};

  Params params;
  // Validates the state (validate(DragState)).
  [[nodiscard]] DragCoefficients evaluate(const DragState& state) const;
  // C_D of Eq. 7.31 at Reynolds number `re` (> 0).
  [[nodiscard]] double dragCoefficient(double re) const;
};

// `ergun_wen_yu`: Eqs. 7.30-7.31 as printed (n -2.7, C_D,Newton 0.43).
struct ErgunWenYuAsPrinted : ErgunWenYu {
  static constexpr const char* name = "ergun_wen_yu";
  static constexpr const char* doc = "Ergun / Wen-Yu drag as printed (-2.7, C_D 0.43), the TF-DEM default";
  // Eq. 7.30 at eps_g 0.8, Ergun (189.6 kg/(m^3 s)) against Wen-Yu (100.8) at the reference
  // state (python3): the law jumps by construction, as printed.
  static constexpr std::array<DragSwitch, 1> switches{{{kErgunVoidFraction, -0.46815755}}};
  ErgunWenYuAsPrinted() : ErgunWenYu(asPrinted()) {}
};

// `gidaspow`: Gidaspow's published form (n -2.65, C_D,Newton 0.44).
struct Gidaspow : ErgunWenYu {
  static constexpr const char* name = "gidaspow";
  static constexpr const char* doc = "Ergun / Wen-Yu drag in Gidaspow's published form (-2.65, C_D 0.44)";
  // As ergun_wen_yu's, the Wen-Yu side 0.8^0.05 lower (99.72 against 189.6, python3).
  static constexpr std::array<DragSwitch, 1> switches{{{kErgunVoidFraction, -0.47405844}}};
  Gidaspow() : ErgunWenYu(gidaspow()) {}
};

}  // namespace grainbridge::closures
