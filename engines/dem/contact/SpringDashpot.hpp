#pragma once
// The soft-sphere contact law of Silbert et al. (2001) as the reference writes it, Eqs. 6.1-6.6:
//
//   F_n = f(delta/d) ( k_n delta n - gamma_n m_eff v_n )                     (6.5)
//   F_t = f(delta/d) ( -k_t u_t - gamma_t m_eff v_t ),  |F_t| <= mu |F_n|     (6.6)
//
// with f = 1 (linear spring-dashpot) or f = sqrt(delta/d) (Hertzian, `Hertz` below; d = a_i + a_j
// for a pair and 2 a_i against a wall). This is the reference law to copy when adding one: a
// small value type, one evaluate() that the pair and wall loops inline, no virtual calls.
//
// u_t, the elastic tangential displacement, lives as long as the contact (history). Each step,
// before it is advanced, it is projected onto the current tangent plane and rescaled to its
// old length: the rigid-rotation correction that is the last term of Eq. 6.4, applied in a form
// that stays stable over long-lasting contacts (a stuck pair spun for many turns keeps |F_t|).
// When the Coulomb limit caps the force, u_t is reset to the value that gives the capped force,
// so a sliding contact does not store unbounded elastic displacement.
#include <cmath>

#include "core/Types.hpp"
#include "engines/dem/Material.hpp"

namespace grainbridge::dem::contact {

// Relative motion at one contact, all as seen by particle i (n points from j to i).
struct ContactKinematics {
  Vec3 n;        // unit normal, from j towards i
  double delta;  // overlap d - r_ij (Eq. 6.1), > 0
  double d;      // a_i + a_j (2 a_i for a wall): the length in f(delta/d)
  Vec3 vn;       // normal relative velocity (Eq. 6.2)
  Vec3 vt;       // tangential relative velocity of the contact surfaces (Eq. 6.3)
  double meff;   // m_i m_j / (m_i + m_j); the mobile partner's mass against a frozen one or a wall
};

// Force on particle i, split into its elastic (spring) and dissipative (dashpot) parts.
struct ContactForce {
  Vec3 normalElastic;
  Vec3 normalDissipative;
  Vec3 tangentialElastic;
  Vec3 tangentialDissipative;
  [[nodiscard]] Vec3 normal() const { return normalElastic + normalDissipative; }
  [[nodiscard]] Vec3 tangential() const { return tangentialElastic + tangentialDissipative; }
};

struct Linear {
  static constexpr const char* name = "linear";
  static double scale(double /*delta*/, double /*d*/) { return 1.0; }
};

struct Hertz {
  static constexpr const char* name = "hertz";
  static double scale(double delta, double d) { return std::sqrt(delta / d); }  // Eq. 6.5, Silbert 2001
};

template <class Stiffness>
struct SpringDashpot {
  // Advances the history u_t by one step of dt and returns the force on i. About 60 flops.
  static ContactForce evaluate(const ContactKinematics& c, const PairMaterial& m, double dt, Vec3& ut) {
    const double f = Stiffness::scale(c.delta, c.d);
    ContactForce out;
    out.normalElastic = (f * m.kn * c.delta) * c.n;
    out.normalDissipative = (-f * m.gammaN * c.meff) * c.vn;

    // Eq. 6.4: keep u_t in the tangent plane under rigid rotation (project, restore length),
    // then integrate the slip.
    const double before2 = ut.squaredNorm();
    if (before2 > 0.0) {
      ut -= ut.dot(c.n) * c.n;
      const double after2 = ut.squaredNorm();
      if (after2 > 0.0) ut *= std::sqrt(before2 / after2);
    }
    ut += c.vt * dt;

    out.tangentialElastic = (-f * m.kt) * ut;
    out.tangentialDissipative = (-f * m.gammaT * c.meff) * c.vt;
    const double limit = m.mu * out.normal().norm();
    const Vec3 ft = out.tangential();
    const double ft2 = ft.squaredNorm();
    if (ft2 > limit * limit) {
      // Sliding: cap |F_t| at mu |F_n| and reset u_t to the displacement that gives it.
      const Vec3 capped = ft * (limit / std::sqrt(ft2));
      if (m.kt > 0.0 && f > 0.0) {
        ut = -(capped / f + m.gammaT * c.meff * c.vt) / m.kt;
        out.tangentialElastic = (-f * m.kt) * ut;
      } else {
        ut.setZero();
        out.tangentialElastic = capped - out.tangentialDissipative;
      }
    }
    return out;
  }
};

}  // namespace grainbridge::dem::contact
