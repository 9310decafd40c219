#pragma once
// The reference's printed granular stress closure (Syamlal 1987b, Section 3.1.2.5): the
// coefficients K1..K3 of Eqs. 3.21-3.25 and K4 of the dissipation gamma = K4 eps^2 theta^1.5
// (Section 3.1.2.9; the K4 MFIX uses is Eq. 5.7's 12 (1 - e^2) rho g0 / (sqrt(pi) d)).
// MFIX solves it with an algebraic granular temperature (gt_algebraic in model/calc_mu_s.f).
// It has no kinetic pressure and a shear viscosity that vanishes with eps, so at low solid
// fraction it is far from Lun1984 (VALIDATION.md: report that deviation, do not test it).
//
//   P      = K1 eps^2 theta                                  (Eq. 3.21)
//   lambda = K2 eps sqrt(theta)   (second viscosity, Eq. 3.22; xi = lambda + 2/3 mu)
//   mu     = K3 eps sqrt(theta)                              (Eq. 3.22)
//   K1 = 2 (1 + e) rho g0                                    (Eq. 3.23)
//   K2 = 4 d rho (1 + e) eps g0 / (3 sqrt(pi)) - 2/3 K3      (Eq. 3.24)
//   K3 = d rho / 2 { sqrt(pi) / (3 (3 - e)) [L + 0.4 (1 + e)(3e - 1) eps g0]
//                    + 8 eps g0 (1 + e) / (5 sqrt(pi)) }     (Eq. 3.25)
//   K4 = 12 (1 - e^2) rho g0 / (sqrt(pi) d)                  (Eq. 5.7; MFIX K_4m)
// The leading term L of Eq. 3.25 comes in two forms (VALIDATION.md):
//   Printed: L = 1, as printed in Eq. 3.25 and in an older MFIX calc_mu_s.f (the fixed-form
//            source with D_p(M)). The default ("syamlal_algebraic").
//   Mfix:    L = (3e + 1)/2, as in MFIX's gt_algebraic K_3m from the 2005 modular rewrite
//            through MFIX 21.3 ("syamlal_algebraic_mfix").
// Only the kinetic (eps-linear) viscosity term changes, and K2 through -2/3 K3: the pressure,
// the bulk viscosity xi, the conductivity and the dissipation are the same in both forms. The
// two shear viscosities coincide only at e = 1/3; at e = 1 the Mfix kinetic term is twice the
// printed one (mu_Mfix - mu_Printed = sqrt(pi) (3e - 1) / (12 (3 - e)) rho d eps sqrt(theta)).
//
// Conductivity (the reference prints none, VALIDATION.md): Syamlal, Rogers & O'Brien (1993),
// MFIX Documentation Theory Guide, DOE/METC-94/1004, as also implemented by OpenFOAM's
// "Syamlal" conductivityModel, with eta = (1 + e)/2:
//   kappa = 15 d rho eps sqrt(pi theta) / (4 (41 - 33 eta))
//           [1 + 12/5 eta^2 (4 eta - 3) eps g0 + 16 / (15 pi) (41 - 33 eta) eta eps g0].
// An algebraic granular temperature neglects conduction, so this is only used if the energy
// equation is solved as a PDE with this model.
#include <string_view>

#include "engines/closures/KineticState.hpp"

namespace grainbridge::closures {

enum class SyamlalViscosityForm {
  Printed,  // Eq. 3.25 as printed: leading term 1
  Mfix,     // MFIX gt_algebraic: leading term (3e + 1)/2
};

// K1 [kg/m^3], K2 and K3 [kg/m^2], K4 [kg/m^4] of Eqs. 3.23-3.25 and 5.7; they depend on eps
// (through g0 and explicitly) but not on theta, which is why an algebraic temperature solver
// wants them separately.
struct SyamlalCoefficients {
  double k1 = 0.0;
  double k2 = 0.0;
  double k3 = 0.0;
  double k4 = 0.0;
};

struct SyamlalAlgebraic {
  struct Params {
    SyamlalViscosityForm viscosityForm = SyamlalViscosityForm::Printed;
  };
  Params params;

  // "syamlal_algebraic" (Printed) or "syamlal_algebraic_mfix" (Mfix).
  [[nodiscard]] std::string_view name() const;
  // Validates the state; the granular temperature is not used.
  [[nodiscard]] SyamlalCoefficients coefficients(const KineticState& state) const;
  // Validates the state and returns all five coefficients.
  [[nodiscard]] KineticTransport evaluate(const KineticState& state) const;
};

}  // namespace grainbridge::closures
