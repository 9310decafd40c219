#pragma once
// Normal spring sub-models: the factor f(delta/d) of Eqs. 6.5-6.6 that scales every spring and
// (for mass-scaled damping) every dashpot of the contact,
//   F_n,el = f(delta/d) k_n delta n.
// Each declares its name (the `normal_model` key) and whether the contact is linear, in which
// case restitution and contact time have the closed forms of Eqs. 6.9-6.10.
#include <cmath>

namespace grainbridge::dem::contact {

struct LinearSpring {
  static constexpr const char* name = "linear";
  static constexpr const char* doc = "f = 1: linear spring (Eq. 6.5)";
  static constexpr bool closedFormCollision = true;  // Eqs. 6.9-6.10
  [[gnu::always_inline]] static double scale(double /*delta*/, double /*d*/) { return 1.0; }
};

struct HertzSpring {
  static constexpr const char* name = "hertz";
  static constexpr const char* doc = "f = sqrt(delta/d): Hertzian spring (Eq. 6.5, Silbert et al. 2001)";
  // The restitution of a Hertzian contact depends on the impact speed: no closed form.
  static constexpr bool closedFormCollision = false;
  [[gnu::always_inline]] static double scale(double delta, double d) { return std::sqrt(delta / d); }
};

}  // namespace grainbridge::dem::contact
