#pragma once
// Small builders for DEM physics tests: Table 6.1 materials in reduced units (d0 = m0 = g = 1,
// so t0 = 1 and k0 = 1), and one- or two-particle setups.
#include <cmath>

#include "engines/dem/Simulation.hpp"

namespace grainbridge::dem::testing {

inline double sphereMass(double d, double density) { return density * M_PI / 6.0 * d * d * d; }

// Table 6.1 particle-particle coefficients (reduced units).
inline PairMaterial table61Particle() {
  PairMaterial m;
  m.kn = 2e5;
  m.kt = 2.0 / 7.0 * m.kn;
  m.gammaN = 40.0;
  m.gammaT = 0.0;
  m.mu = 0.5;
  return m;
}

// Table 6.1 wall coefficients.
inline PairMaterial table61Wall(double mu = 0.5) {
  PairMaterial m = table61Particle();
  m.gammaT = 20.0;
  m.mu = mu;
  return m;
}

inline SimulationSetup openBox(const PairMaterial& pair, int species = 1, double dt = 2e-4) {
  SimulationSetup s;
  s.lo = Vec3::Constant(-50.0);
  s.hi = Vec3::Constant(50.0);
  s.dt = dt;
  s.skin = 0.3;
  s.species = species;
  s.pairMaterial.assign(static_cast<std::size_t>(species * species), pair);
  return s;
}

inline Wall floorWall(const PairMaterial& m, double z = 0.0, int species = 1) {
  Wall w;
  w.kind = Wall::Kind::Plane;
  w.origin = Vec3(0, 0, z);
  w.direction = Vec3::UnitZ();
  w.material.assign(static_cast<std::size_t>(species), m);
  return w;
}

}  // namespace grainbridge::dem::testing
