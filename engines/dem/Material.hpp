#pragma once
// Contact coefficients of one pair of surfaces (two species, or a species and a wall), in the
// form the contact sub-models (contact/*Models.hpp) read them: k_n, k_t spring constants [N/m],
// gamma_n, gamma_t damping rates [1/s] (times m_eff in the force, mass_scaled damping), eta_n,
// eta_t dashpot coefficients [kg/s] (dimensional damping), mu the Coulomb friction coefficient.
// A pair may be given by restitution instead: contact/Conversions.hpp sets its normal damping
// for that pair's m_eff (STYLE.md 6: physical inputs in, loop coefficients precomputed once).
#include <string>

namespace grainbridge::dem {

struct PairMaterial {
  double kn = 0.0;
  double kt = 0.0;
  double gammaN = 0.0;
  double gammaT = 0.0;
  double mu = 0.0;
  double etaN = 0.0;
  double etaT = 0.0;
};

// Eq. 6.10: t_c = pi (k_n/m_eff - gamma_n^2/4)^(-1/2) of the linear model; +inf when the pair is
// overdamped (no rebound, no contact time).
double linearContactTime(double kn, double gammaN, double meff);
// Eq. 6.9: e_n = exp(-gamma_n t_c / 2).
double linearRestitution(double kn, double gammaN, double meff);
// Inverse of Eqs. 6.9-6.10: the gamma_n giving restitution e (0 < e <= 1) at this k_n, m_eff.
double gammaForRestitution(double e, double kn, double meff);

}  // namespace grainbridge::dem
