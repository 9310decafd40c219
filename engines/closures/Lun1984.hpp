#pragma once
// Kinetic theory of Lun, Savage, Jeffrey & Chepurniy (1984), J. Fluid Mech. 140:223-256, for
// smooth, slightly inelastic, identical spheres: kinetic + collisional parts of the pressure,
// viscosities and conductivity, with the Ma & Ahmadi (1988, Powder Technol. 56:191-207)
// reduction of the dilute viscosity and conductivity by an interstitial gas. This is what the
// reference's Chapter 5 ran in MFIX (Section 5.2.1, line ~1090) and the default model; the
// compare stage checks DEM simple shear against it (VALIDATION.md, kinetic theory against DEM).
//
// Source of the formulas as written here: MFIX's LUN_1984 option, subroutine gt_pde_lun in
// model/calc_mu_s.f (read in MFIX 21.3 and a 2005 version), for one solids phase (MFIX's
// SUM_EpsGo = eps g0). MFIX multiplies the whole shear viscosity (with its 3/5 xi) by
// (2 + alpha)/3 with alpha = 1.6 (its own comment says Lun's theory has alpha = 1): the form
// "lun1984" is the published alpha = 1 one (VALIDATION.md), "lun1984_mfix" is MFIX's, whose
// viscosity is 1.2 times it (and whose second viscosity lambda = xi - 2/3 mu follows).
//
// With eta = (1 + e)/2, g0 = carnahanStarlingG0(eps), mu0 = 5 sqrt(pi)/96 rho d sqrt(theta)
// (Chapman-Enskog viscosity of elastic hard spheres) and
// kappa0 = 25 sqrt(pi) / (16 eta (41 - 33 eta)) rho d sqrt(theta):
//   p     = rho eps theta (1 + 4 eta eps g0)
//   xi    = 8 eta / (3 sqrt(pi)) rho d eps^2 g0 sqrt(theta)                        (bulk)
//   mu    = mu* / (eta (2 - eta) g0) (1 + 8/5 eta eps g0)(1 + 8/5 eta (3 eta - 2) eps g0)
//           + 3/5 xi                                    (3/5 xi = MFIX's 0.6 eta Mu_b)
//   kappa = kappa* / g0 (1 + 12/5 eta eps g0)(1 + 12/5 eta^2 (4 eta - 3) eps g0)
//           + 4 eta / sqrt(pi) rho d eps^2 g0 sqrt(theta)
//                                   (= 64/(25 pi) (41 - 33 eta) eta^2 eps^2 g0 kappa0)
//   J     = 12/sqrt(pi) (1 - e^2) rho eps^2 g0 theta^(3/2) / d                       (Eq. 5.7)
// Ma-Ahmadi, as MFIX writes it with beta the gas drag coefficient:
//   mu*    = mu0    / (1 + 2   beta mu0    / (rho^2 eps^2 g0 theta))
//   kappa* = kappa0 / (1 + 1.2 beta kappa0 / (rho^2 eps^2 g0 theta))
// so beta = 0 gives the pure Lun et al. (1984) coefficients. A phase of a mixture (KineticState's
// g0, contactSum, dissipationSum) reads eps g0 as S = sum_l eps_l g0_ml everywhere above, g0 as
// g0_mm, the collisional conductivity as 4 eta/sqrt(pi) rho d eps S sqrt(theta), J with
// sum_l eps_l g0_ll, and c* = c0 (eps g0_mm / S) a / (a + factor beta c0), a = rho^2 eps S theta,
// as MFIX does since 2005, so that identical phases add up to one; and in the dilute limit
// (eps -> 0, beta = 0, e = 1) mu -> 5/96 rho d sqrt(pi theta) and kappa -> 25 sqrt(pi)/128
// rho d sqrt(theta), the Chapman-Enskog values; for e < 1 the dilute mu carries 1/(eta (2 - eta)).
#include <string_view>

#include "engines/closures/KineticState.hpp"

namespace grainbridge::closures {

enum class Lun1984ViscosityForm {
  Published,  // "lun1984": alpha = 1
  Mfix,       // "lun1984_mfix": mu times (2 + alpha)/3 = 1.2, alpha = 1.6, as MFIX calc_mu_s.f
};

struct Lun1984 {
  Lun1984ViscosityForm viscosityForm = Lun1984ViscosityForm::Published;

  [[nodiscard]] constexpr std::string_view name() const {
    return viscosityForm == Lun1984ViscosityForm::Published ? "lun1984" : "lun1984_mfix";
  }
  // MFIX's (2 + alpha)/3 with its alpha = 1.6, or 1.
  [[nodiscard]] constexpr double viscosityFactor() const {
    return viscosityForm == Lun1984ViscosityForm::Published ? 1.0 : (2.0 + 1.6) / 3.0;
  }
  // Validates the state (validate(KineticState)) and returns all five coefficients.
  [[nodiscard]] KineticTransport evaluate(const KineticState& state) const;
};

}  // namespace grainbridge::closures
