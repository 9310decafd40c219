#pragma once
// Tangential sub-models: the elastic displacement u_t a contact keeps for its lifetime (its
// history, one Vec3), the tangential spring -f k_t u_t plus the damping model's dashpot, and the
// Coulomb cap |F_t| <= mu |F_n| on the whole normal force (Eq. 6.6). They differ in the order in
// which the history is moved on:
// - `history` (the default, Eq. 6.4 as the reference writes it): u_t is projected onto the
//   current tangent plane and rescaled to its old length (the rigid-rotation term of Eq. 6.4 in
//   a form that stays stable over long contacts: a stuck pair spun for many turns keeps |F_t|),
//   then the slip v_t dt is added. Capped, u_t is reset to the displacement that gives the capped
//   force.
// - `lammps_history` (LAMMPS gran/hooke/history, to reproduce a LAMMPS run): the slip is added
//   first, then u_t is projected onto the tangent plane without rescaling; capped, u_t is reset
//   by LAMMPS's formula, and a contact whose u_t was zero gets no tangential force at all.
// With History::Keep neither moves u_t (the set-up evaluation of a run).
#include <cmath>

#include "engines/dem/Material.hpp"
#include "engines/dem/contact/ContactKinematics.hpp"

namespace grainbridge::dem::contact {

// Whether |F_t|^2 = ft2 is below the Coulomb cap (mu |F_n|)^2 (fn2 = |F_n|^2) by a margin far
// beyond round-off, so that the exact test, with its square roots, would say the same. Most
// contacts of a settled bed stick: they skip both square roots and take the same branch with
// the same bits. The margin (1e-9 relative) covers the few ulps of error in either product; a
// contact closer to the cap than that, or a NaN, goes on to the exact test.
[[gnu::always_inline]] inline bool surelyUnderCap(double ft2, double mu, double fn2) {
  constexpr double kMargin = 1.0 - 1e-9;
  return ft2 < kMargin * ((mu * mu) * fn2);
}

// The factor that gives a projected history back its old length (Eq. 6.4's rescale):
// |u| / |u_p| for u_p = u - (u.n) n, |u|^2 = before2, (u.n)^2 = along2. With s = along2 / before2,
// the squared cosine of the angle between u and the normal, it is 1 / sqrt(1 - s). A contact
// turns little in one step (s ~ (|v_t| dt / d)^2: of order 1e-14 in a settled bed, 1e-7 in a
// collision of a fast sheared gas; estimates, not measured), and for
// s < 1e-4 the series 1 + s/2 + 3s^2/8 + 5s^3/16 is within 3e-17 of it: below an ulp of 1, as
// right as sqrt(before2 / after2), which it replaces there. Why: that division and square root
// came at the end of the contact's longest dependency chain and cost the dense bed 10 % of its
// run time (perf; the probe with them removed), while 1 / before2 can start as soon as u_t is
// loaded. Larger turns, and a u_t along the normal, take the direct form.
[[gnu::always_inline]] inline double lengthRestoringFactor(double before2, double along2, const Vec3& projected) {
  const double s = along2 * (1.0 / before2);
  if (s < 1e-4) return 1.0 + s * (0.5 + s * (0.375 + s * 0.3125));
  const double after2 = projected.squaredNorm();
  return after2 > 0.0 ? std::sqrt(before2 / after2) : 1.0;
}

struct ProjectedHistory {
  static constexpr const char* name = "history";
  static constexpr const char* doc = "Eq. 6.4: u_t projected and rescaled, then advanced by v_t dt (the reference)";
  static constexpr int historySize = 3;  // u_t

  template <class Damping>
  [[gnu::always_inline]] static void apply(const ContactKinematics& c, const PairMaterial& m, double f, double dt,
                                           Vec3& ut, History h, ContactForce& out) {
    if (h == History::Advance) {
      const double before2 = ut.squaredNorm();
      if (before2 > 0.0) {
        const double alongBranch = ut.dot(c.branch);          // |r| (u.n)
        const double alongScale = alongBranch * c.invBranch2;  // (u.n) / |r|
        ut -= alongScale * c.branch;
        ut *= lengthRestoringFactor(before2, alongBranch * alongScale, ut);
      }
      ut += c.vt * dt;
    }
    out.tangentialElastic = (-f * m.kt) * ut;
    out.tangentialDissipative = Damping::tangential(c, m, f);
    const Vec3 ft = out.tangential();
    const double ft2 = ft.squaredNorm();
    const double fn2 = out.normal().squaredNorm();
    if (surelyUnderCap(ft2, m.mu, fn2)) return;
    const double limit = m.mu * std::sqrt(fn2);
    if (ft2 <= limit * limit) return;
    // Sliding: cap |F_t| at mu |F_n| and reset u_t to the displacement that gives it.
    const Vec3 capped = ft * (limit / std::sqrt(ft2));
    if (m.kt > 0.0 && f > 0.0 && h == History::Advance) {
      ut = -(capped / f + Damping::tangentialPerScale(c, m, f)) / m.kt;
      out.tangentialElastic = (-f * m.kt) * ut;
    } else {
      if (h == History::Advance) ut.setZero();
      out.tangentialElastic = capped - out.tangentialDissipative;
    }
  }
};

struct LammpsHistory {
  static constexpr const char* name = "lammps_history";
  static constexpr const char* doc =
      "LAMMPS gran/hooke/history: u_t advanced, then projected without rescaling; to reproduce LAMMPS runs";
  static constexpr int historySize = 3;  // u_t ("shear" in LAMMPS)

  template <class Damping>
  [[gnu::always_inline]] static void apply(const ContactKinematics& c, const PairMaterial& m, double f, double dt,
                                           Vec3& ut, History h, ContactForce& out) {
    const bool advance = h == History::Advance;
    if (advance) ut += c.vt * dt;
    const double before = ut.squaredNorm();  // LAMMPS's shrmag, taken before the projection
    if (advance) ut -= c.alongNormal(ut);  // LAMMPS: rsht = shear . del rsqinv
    out.tangentialElastic = (-f * m.kt) * ut;
    out.tangentialDissipative = Damping::tangential(c, m, f);
    const double fs2 = out.tangential().squaredNorm();
    const double fn2 = out.normal().squaredNorm();
    if (surelyUnderCap(fs2, m.mu, fn2)) return;
    const double fs = std::sqrt(fs2);
    const double fn = m.mu * std::sqrt(fn2);
    if (!(fs > fn)) return;
    if (before != 0.0) {
      const double ratio = fn / fs;
      if (advance && m.kt > 0.0 && f > 0.0) {
        const Vec3 offset = Damping::tangentialPerScale(c, m, f) / m.kt;
        ut = ratio * (ut + offset) - offset;
      }
      out.tangentialElastic *= ratio;
      out.tangentialDissipative *= ratio;
    } else {
      out.tangentialElastic.setZero();
      out.tangentialDissipative.setZero();
    }
  }
};

}  // namespace grainbridge::dem::contact
