#pragma once
// Rigid boundaries of infinite mass: planes and a cylinder (the Brazil-nut container), each
// optionally vibrating as A sin(2 pi f t) along a direction. A wall's velocity enters every
// contact's relative velocity exactly as a particle's would (Eqs. 6.2-6.4): that is how a
// vibrating container's side wall exerts friction on the bed. Against a wall the particle's
// radius is the lever arm and d = 2 a_i in the Hertz factor.
#include <cmath>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "engines/dem/Material.hpp"

namespace grainbridge::dem {

struct Vibration {
  Vec3 direction = Vec3::UnitZ();
  double amplitude = 0.0;  // m
  double frequency = 0.0;  // Hz (ordinary frequency: omega = 2 pi f)
  [[nodiscard]] Vec3 displacement(double t) const {
    return amplitude * std::sin(2.0 * M_PI * frequency * t) * direction;
  }
  [[nodiscard]] Vec3 velocity(double t) const {
    return amplitude * 2.0 * M_PI * frequency * std::cos(2.0 * M_PI * frequency * t) * direction;
  }
};

struct Wall {
  enum class Kind { Plane, Cylinder };
  Kind kind = Kind::Plane;
  Vec3 origin = Vec3::Zero();      // a point on the plane, or on the cylinder axis, at rest
  Vec3 direction = Vec3::UnitZ();  // plane: unit normal pointing into the domain; cylinder: axis
  double radius = 0.0;             // cylinder: inner radius (particles inside)
  Vibration vibration;
  std::vector<PairMaterial> material;  // per particle species

  [[nodiscard]] Vec3 positionAt(double t) const { return origin + vibration.displacement(t); }
  [[nodiscard]] Vec3 velocityAt(double t) const { return vibration.velocity(t); }
};

}  // namespace grainbridge::dem
