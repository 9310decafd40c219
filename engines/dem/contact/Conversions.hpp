#pragma once
// From physical inputs to a law's coefficients (STYLE.md 6): the restitution and contact time of
// a head-on collision under any composition, and the normal damping that gives an asked
// restitution. A linear spring has the closed forms of Eqs. 6.9-6.10; any other normal model is
// integrated (a Hertzian contact's restitution depends on the impact speed, so it is asked for at
// a stated one).
#include <optional>

#include "engines/dem/Material.hpp"
#include "engines/dem/contact/ContactModels.hpp"

namespace grainbridge::dem::contact {

struct CollisionResponse {
  double restitution = 0.0;  // e_n = -v_n,out / v_n,in; 0 when the contact never ends (overdamped)
  double contactTime = 0.0;  // +inf when the contact never ends
};

// Whether the law's restitution is independent of impact speed (Eqs. 6.9-6.10 hold).
[[nodiscard]] bool hasClosedFormCollision(const AnyContactLaw& law);

// A head-on collision of two bodies of reduced mass meff whose contact length is d (a_i + a_j;
// 2 a_i against a wall) approaching at impactSpeed: closed form for a linear spring, else
// integrated (RK4, 2000 steps per linear contact time at least) until the overlap returns to 0.
[[nodiscard]] CollisionResponse headOnCollision(const AnyContactLaw& law, const PairMaterial& m, double meff, double d,
                                                double impactSpeed);

// The linear spring's Eqs. 6.9-6.10 with the law's normal damping rate, whatever its spring: the
// estimate for a Hertzian pair when no impact speed is stated (its t_c is then a lower bound).
[[nodiscard]] CollisionResponse linearEstimate(const AnyContactLaw& law, const PairMaterial& m, double meff);

// The material with its normal damping (gamma_n or eta_n, as the law's damping model reads it)
// set so that a head-on collision at impactSpeed rebounds with restitution e (0 < e <= 1).
// Closed form (Eqs. 6.9-6.10 inverted) for a linear spring; bisection otherwise, to 1e-10 in e.
[[nodiscard]] PairMaterial withRestitution(const AnyContactLaw& law, PairMaterial m, double e, double meff, double d,
                                           double impactSpeed);

// The material with k_n set so that a head-on collision lasts contactTime (Eq. 6.10 inverted:
// k_n = m_eff (pi^2 / t_c^2 + gamma_n^2 / 4)); with a restitution e (0 < e <= 1) the normal
// damping is set too (Eq. 6.9: gamma_n = -2 ln(e) / t_c), else the material's own is kept. Only
// for laws with a closed-form collision (a linear spring): a Hertzian contact time depends on the
// impact speed, and the dem stage refuses contact_time there.
[[nodiscard]] PairMaterial withContactTime(const AnyContactLaw& law, PairMaterial m, double contactTime,
                                           std::optional<double> restitution, double meff);

}  // namespace grainbridge::dem::contact
