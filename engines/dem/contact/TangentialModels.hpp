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
        ut -= ut.dot(c.n) * c.n;
        const double after2 = ut.squaredNorm();
        if (after2 > 0.0) ut *= std::sqrt(before2 / after2);
      }
      ut += c.vt * dt;
    }
    out.tangentialElastic = (-f * m.kt) * ut;
    out.tangentialDissipative = Damping::tangential(c, m, f);
    const double limit = m.mu * out.normal().norm();
    const Vec3 ft = out.tangential();
    const double ft2 = ft.squaredNorm();
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
    if (advance) ut -= ut.dot(c.n) * c.n;
    out.tangentialElastic = (-f * m.kt) * ut;
    out.tangentialDissipative = Damping::tangential(c, m, f);
    const double fs = out.tangential().norm();
    const double fn = m.mu * out.normal().norm();
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
