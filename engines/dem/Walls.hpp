#pragma once
// Rigid boundaries of infinite mass: planes and a cylinder (the Brazil-nut container), each
// optionally vibrating along a direction, as A sin(2 pi f t) or, started at rest,
// A (1 - cos 2 pi f t). A wall's velocity enters every
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
  // MidStroke: A sin(2 pi f t), the wall passes its rest position at full speed at t = 0.
  // AtRest: A (1 - cos 2 pi f t), the wall starts at rest and swings between its rest position
  // and 2 A from it, with no jump in velocity at t = 0 (LAMMPS's fix wall/gran wiggle).
  enum class Start { MidStroke, AtRest };
  Vec3 direction = Vec3::UnitZ();
  double amplitude = 0.0;  // m
  double frequency = 0.0;  // Hz (ordinary frequency: omega = 2 pi f)
  Start start = Start::MidStroke;
  [[nodiscard]] bool active() const { return amplitude != 0.0 && frequency != 0.0; }
  [[nodiscard]] Vec3 displacement(double t) const {
    const double phase = 2.0 * M_PI * frequency * t;
    return amplitude * (start == Start::AtRest ? 1.0 - std::cos(phase) : std::sin(phase)) * direction;
  }
  [[nodiscard]] Vec3 velocity(double t) const {
    const double phase = 2.0 * M_PI * frequency * t;
    return amplitude * 2.0 * M_PI * frequency * (start == Start::AtRest ? std::sin(phase) : std::cos(phase)) *
           direction;
  }
};

[[nodiscard]] const char* vibrationStartName(Vibration::Start start);
// "mid_stroke" or "at_rest"; throws on anything else.
[[nodiscard]] Vibration::Start vibrationStartFromName(const std::string& name);

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
