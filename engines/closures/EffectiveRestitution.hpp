#pragma once
// The particle-rotation model of the reference's Section 5.2.2 (Eqs. 5.11-5.19, after Jenkins
// and Zhang 2002, Phys. Fluids 14(3):1228-1235): slightly frictional, nearly elastic spheres
// lose translational fluctuation energy to rotation and sliding; with the rotational
// temperature at its balance (Eq. 5.18) the loss is that of frictionless spheres with an
// effective restitution e_eff < e:
//
//   mu0   = 7/2 mu (1 + e) / (1 + beta0)                                               (5.17)
//   a1    = mu/mu0 [pi mu0 (1 - 2/pi atan mu0) + 2 mu0^2/(1 + mu0^2) (1 - 2 mu/mu0)]    (5.12)
//   a2    = 5 mu/mu0 [pi/2 mu0 (1 - 2/pi atan mu0) - mu0^4/(1 + mu0^2)^2]               (5.13)
//   b1    = (mu/mu0)^2 mu0^2/(1 + mu0^2)                                                (5.15)
//   b2    = mu/(2 mu0) [pi/2 mu0 (1 - 2/pi atan mu0) + mu0^2/(1 + mu0^2)]               (5.16)
//   theta_r / theta_t = b1 / b2                                                         (5.18)
//   e_eff = e - a1/2 + a2 b1 / (2 b2)                                                   (5.19)
//
// e_eff enters only the collisional dissipation (Eq. 5.20) and the wall energy flux (Eq. 5.21),
// both as (1 + e)(1 - e_eff) where the frictionless forms have (1 - e^2): dissipationFactor().
// Everything else (pressure, viscosity, solids-solids drag) keeps e (VALIDATION.md: replacing e
// by e_eff everywhere raises the Goldschmidt bed twice as much as the reference's model does).
// Table 5.1 (e = 0.97, beta0 = 0.33): mu 0.15 -> 0.82544, 0.10 -> 0.86206, wall 0.09 -> 0.87010.
#include <string_view>

namespace grainbridge::closures {

struct EffectiveRestitution {
  struct Params {
    double friction = 0.0;                // mu, Coulomb friction coefficient of the surfaces [-], >= 0
    double tangentialRestitution = 0.33;  // beta0 of Eq. 5.17, in [-1, 1]: Table 5.1's value
  };
  struct Result {
    double effectiveRestitution = 1.0;                         // e_eff, Eq. 5.19
    double rotationalToTranslational = 0.0;                    // theta_r / theta_t, Eq. 5.18
    double a1 = 0.0, a2 = 0.0, b1 = 0.0, b2 = 0.0, mu0 = 0.0;  // Eqs. 5.12-5.17
    // (1 + e)(1 - e_eff): what replaces (1 - e^2) in Eqs. 5.20 and 5.21.
    double dissipationFactor = 0.0;
  };

  [[nodiscard]] static constexpr std::string_view name() { return "effective_restitution"; }
  Params params;
  // For normal restitution e in (0, 1]. Frictionless surfaces (mu = 0) give e_eff = e, the limit
  // of Eqs. 5.12-5.19 (every term carries mu/mu0 times a bracket that vanishes with mu0).
  // Throws grainbridge::Error naming a value out of range.
  [[nodiscard]] Result evaluate(double restitution) const;
};

}  // namespace grainbridge::closures
