#pragma once
// What every contact sub-model works from and returns: the relative motion at one contact
// (Eqs. 6.1-6.3) and the force on particle i split into elastic and dissipative parts.
#include "core/Types.hpp"

namespace grainbridge::dem::contact {

// Relative motion at one contact, all as seen by particle i (n points from j to i).
struct ContactKinematics {
  Vec3 n;        // unit normal, from j towards i
  // The normal before it was made a unit vector, and 1 / |branch|^2: a pair's r_ij and 1 / r^2.
  // What is projected onto the normal is projected with them (as LAMMPS does): 1 / r^2 is ready
  // a square root and a division sooner than n, which shortens the contact's longest dependency
  // chain. Set all three with setBranch (a pair) or setUnitNormal (a wall: branch = n,
  // invBranch2 = 1).
  Vec3 branch;
  double invBranch2;
  double delta;  // overlap d - r_ij (Eq. 6.1), > 0
  double d;      // a_i + a_j (2 a_i for a wall): the length in f(delta/d)
  Vec3 vn;       // normal relative velocity (Eq. 6.2)
  Vec3 vt;       // tangential relative velocity of the contact surfaces (Eq. 6.3)
  double meff;   // m_i m_j / (m_i + m_j); the mobile partner's mass against a frozen one or a wall

  // A pair's: n from the branch r_ij, its length |r| and 1 / r^2 (1 / |r| as |r| / r^2, so that
  // no division waits for the square root).
  void setBranch(const Vec3& r, double length, double inverseLength2) {
    branch = r;
    invBranch2 = inverseLength2;
    n = r * (length * inverseLength2);
  }
  // n, with branch and invBranch2 to match, from a unit vector (a wall's).
  void setUnitNormal(const Vec3& unit) {
    n = unit;
    branch = unit;
    invBranch2 = 1.0;
  }
  // The part of u along n, (u.n) n, from the branch.
  [[nodiscard]] Vec3 alongNormal(const Vec3& u) const { return (u.dot(branch) * invBranch2) * branch; }
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

// Whether an evaluation moves the contact's history on. A step does; the set-up evaluation of a
// new run (forces for the first half kick, contacts for the first frame) does not, as in LAMMPS
// (`update->setupflag`): otherwise every initial contact would start with its slip counted twice.
enum class History { Advance, Keep };

}  // namespace grainbridge::dem::contact
