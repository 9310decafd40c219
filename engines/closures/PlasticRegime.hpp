#pragma once
// The plastic (slowly shearing, frictional) regime of the solids stress (Section 3.1.2.5):
// below the critical void fraction eps_g* the solids behave as a compressible plastic body with
//
//   P*      = A (eps_g* - eps_g)^n,   A = 1e25 dyn/cm^2 = 1e24 Pa, n = 10   (empirical power law)
//   P^p_sm  = eps_sm P*                                                     (3.26)
//   tau^p_sm = 2 mu^p_sm D_sm                                               (3.27)
//
// and above eps_g* both vanish (the viscous regime, kinetic theory, takes over). The reference
// gives no frictional viscosity or friction angle (VALIDATION.md): Schaeffer (1987, J. Diff.
// Eqs. 66:19-50) as MFIX writes it (model/calc_mu_s.f, FRICTION off):
//
//   mu^p = P* sin(phi) / (2 sqrt(I2D)),  capped at mu_max,
//
// with I2D the second invariant of the deviator of D_s,
// ((D11 - D22)^2 + (D22 - D33)^2 + (D33 - D11)^2) / 6 + D12^2 + D23^2 + D31^2, and MFIX's cap
// MAX_MU_s = 1000 poise = 100 Pa s, which also keeps mu^p finite as the strain rate vanishes.
// MFIX takes P*, not eps_s P*, in the viscosity; so does this. The angle phi is in radians here:
// a config gives it as a quantity ("30 degree"), and a bare number that cannot be an angle in
// radians (30) is refused.
//
// Or, with a mu(I) rheology measured in DEM (`plastic` mu_i, InertialRheology.hpp), the
// frictional viscosity that makes the plastic shear stress mu(I) times the plastic pressure:
//
//   mu^p = mu(I) P^p_s / (2 sqrt(I2D)),   I = 2 sqrt(I2D) d / sqrt(P^p_s / rho_p),
//
// since in simple shear 2 sqrt(I2D) is the shear rate and |tau^p| = 2 mu^p sqrt(I2D). The
// pressure is the plastic pressure of Eq. 3.26, eps_s P*, not Schaeffer's P*: the DEM's stress
// ratio is the shear stress over the pressure of the grains per unit of total volume, which is
// what P^p_s is in the solids momentum equation. The same cap applies (slow shear: I -> 0,
// mu -> mu_s, mu^p -> infinity).
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "engines/closures/InertialRheology.hpp"

namespace grainbridge::closures {

struct PlasticRegime {
  struct Params {
    double criticalVoidFraction = 0.0;          // eps_g* [-], in (0, 1): required (MFIX EP_STAR)
    double coefficient = 1.0e24;                // A [Pa]
    double exponent = 10.0;                     // n [-]
    double internalFrictionAngle = M_PI / 6.0;  // phi [rad], in (0, pi/2): 30 degrees (MFiX run of VALIDATION.md)
    double maxViscosity = 100.0;                // mu_max [Pa s]: MFIX's MAX_MU_s, 1000 poise
    // The mu(I) viscosity instead of Schaeffer's when set (the friction angle is then unused).
    std::optional<InertialRheology> rheology;
    // Why these parameters cannot be used, naming the parameter; empty when they can.
    [[nodiscard]] std::string problem() const;
  };
  struct Result {
    bool plastic = false;    // eps_g < eps_g*
    double pStar = 0.0;      // P* [Pa]
    double pressure = 0.0;   // P^p_sm = eps_sm P* [Pa], Eq. 3.26
    double viscosity = 0.0;  // mu^p_sm [Pa s], Eq. 3.27 with Schaeffer's or the mu(I) viscosity
    double inertialNumber = 0.0;  // I of the mu(I) viscosity (0 with Schaeffer's)
  };

  [[nodiscard]] static constexpr std::string_view name() { return "schaeffer"; }
  Params params;
  // At void fraction eps_g, this phase's solid fraction eps_sm and the second invariant I2D >= 0
  // of the deviator of its strain rate [1/s^2] (the mu(I) viscosity is of one solids phase: a
  // mixture's phases would each need their own grains). Throws grainbridge::Error for unusable params
  // (problem()) or inputs out of range.
  [[nodiscard]] Result evaluate(double voidFraction, double solidFraction, double strainInvariant) const;
  // The same with the cell's own eps_g* in place of params.criticalVoidFraction: a mixture's
  // packing limit by composition (MixturePacking.hpp). Throws unless it is in (0, 1).
  [[nodiscard]] Result evaluate(double voidFraction, double solidFraction, double strainInvariant,
                                double criticalVoidFraction) const;
};

}  // namespace grainbridge::closures
