#pragma once
// What a mixture kinetic theory predicts for steady, homogeneous simple shear of a granular
// mixture without gas (the DEM shear boxes of the mixture closures, issue 60): each phase's
// granular temperature, partial pressure, shear stress and collisional dissipation.
//
// The multi-fluid model gives each solids phase its own granular energy equation (Eq. 3.34) with
// no exchange between phases: in homogeneous shear it reduces to mu_m gammadot^2 = J_m, the phase's
// own shear work against its own collisional dissipation. The kinetic models here have mu_m
// proportional to sqrt(theta_m) and J_m to theta_m^(3/2) at fixed fractions (the Lebowitz g0 and
// the sums of MixtureContacts.hpp do not depend on theta), so theta_m = mu_m(1) gammadot^2 / J_m(1)
// with both at unit temperature, as the compare stage does for one phase.
#include <vector>

#include "engines/closures/KineticModel.hpp"
#include "engines/closures/MixtureContacts.hpp"

namespace grainbridge::closures {

struct ShearedPhase {
  double solidFraction = 0.0;  // eps_m
  double diameter = 0.0;       // d_m [m]
  double density = 0.0;        // rho_m [kg/m^3]
  double restitution = 1.0;    // e_mm
  // J_m over the model's J_m: (1 + e)(1 - e_eff) / (1 - e^2) with the particle-rotation model
  // (EffectiveRestitution.hpp, Eq. 5.20), 1 without; as the multi-fluid model scales it.
  double dissipationScale = 1.0;
};

struct ShearedPhaseState {
  double granularTemperature = 0.0;  // theta_m [m^2/s^2]
  double pressure = 0.0;             // p_m, kinetic + collisional [Pa]
  double kineticPressure = 0.0;      // rho_m eps_m theta_m [Pa]
  double shearStress = 0.0;          // mu_m gammadot [Pa]
  double viscosity = 0.0;            // mu_m [Pa s]
  double dissipationRate = 0.0;      // J_m [W/m^3]
};

// Throws grainbridge::Error for a model whose viscosity or dissipation does not scale with theta
// as above (checked at theta 1 and 4), for no phase, or for a state the model refuses.
[[nodiscard]] std::vector<ShearedPhaseState> mixtureSimpleShear(KineticModelName model, MixtureKineticTheory form,
                                                                const std::vector<ShearedPhase>& phases,
                                                                double shearRate);

}  // namespace grainbridge::closures
