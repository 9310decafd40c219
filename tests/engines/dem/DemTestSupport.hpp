#pragma once
// Small builders for DEM physics tests: Table 6.1 materials in reduced units (d0 = m0 = g = 1,
// so t0 = 1 and k0 = 1), one- or two-particle setups, periodic (sheared) cubes filled at random,
// and the measurement of a collision.
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "engines/dem/Insertion.hpp"
#include "engines/dem/Material.hpp"
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

// A cube [0, side]^3 periodic on all axes, one species of `pair`, sheared (Lees-Edwards) at
// `shearRate` when that is not zero: the box of the gas and simple-shear tests (Chapter 6).
inline SimulationSetup periodicCube(const PairMaterial& pair, double side, double dt, double shearRate = 0.0) {
  SimulationSetup s = openBox(pair, 1, dt);
  s.lo = Vec3::Zero();
  s.hi = Vec3::Constant(side);
  s.periodic = {true, true, true};
  s.shearRate = shearRate;
  return s;
}

// Frictionless spheres of unit mass (m_eff = 1/2) without a tangential spring: k_n, and gamma_n
// from Eq. 6.9 for the normal restitution e.
inline PairMaterial frictionlessUnitMass(double kn, double e) {
  PairMaterial m;
  m.kn = kn;
  m.kt = 0.0;
  m.mu = 0.0;
  m.gammaN = gammaForRestitution(e, kn, 0.5);
  return m;
}

// Unit spheres (d = m = 1) at `centres`, moving with the streaming profile of the Lees-Edwards
// box `s`, u_x = shearRate (y - y_mid): the start of the sheared-box tests.
inline Particles shearedUnitSpheres(const SimulationSetup& s, const std::vector<Vec3>& centres) {
  const double mid = 0.5 * (s.lo[1] + s.hi[1]);
  Particles p;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Vec3& x = centres[i];
    p.addOwned(static_cast<std::int64_t>(i), 0, 0.5, 1.0, x, Vec3(s.shearRate * (x[1] - mid), 0, 0), Vec3::Zero(),
               false);
  }
  return p;
}

// The solid fraction of n unit spheres in the simulation's box as it now is.
inline double unitSphereSolidFraction(const Simulation& sim, int n) {
  const Vec3 l = sim.boxHigh() - sim.boxLow();
  return n * M_PI / 6.0 / (l[0] * l[1] * l[2]);
}

// Centres of n spheres of radius r, inserted at random without overlap in the box of `s`
// (periodic as it is), drawing from `rng`.
inline std::vector<Vec3> randomCentres(const SimulationSetup& s, int n, double r, std::mt19937_64& rng) {
  InsertionRequest rq;
  rq.lo = s.lo;
  rq.hi = s.hi;
  rq.periodic = s.periodic;
  rq.radii.assign(static_cast<std::size_t>(n), r);
  return insertRandomly(rq, rng);
}

inline Wall floorWall(const PairMaterial& m, double z = 0.0, int species = 1) {
  Wall w;
  w.kind = Wall::Kind::Plane;
  w.origin = Vec3(0, 0, z);
  w.direction = Vec3::UnitZ();
  w.material.assign(static_cast<std::size_t>(species), m);
  return w;
}

// A gas of n equal spheres (diameter 1, Table 6.1 small-particle density) at solid fraction phi
// in a cubic box periodic on all axes, no gravity: random non-overlapping centres and
// Maxwellian velocities with zero total momentum, rescaled so that T = <C^2>/3 (Eq. 5.6) is T0.
struct Gas {
  SimulationSetup setup;
  Particles particles;
  double side = 0.0;
};

inline Gas periodicGas(int n, double phi, double T0, const PairMaterial& m, double dt, std::uint64_t seed) {
  Gas g;
  g.side = std::cbrt(n * M_PI / 6.0 / phi);
  g.setup = periodicCube(m, g.side, dt);
  std::mt19937_64 rng(seed);
  const auto centres = randomCentres(g.setup, n, 0.5, rng);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Vec3> v(centres.size());
  Vec3 mean = Vec3::Zero();
  for (auto& vi : v) {
    vi = Vec3(normal(rng), normal(rng), normal(rng));
    mean += vi / static_cast<double>(n);
  }
  double c2 = 0.0;
  for (auto& vi : v) {
    vi -= mean;
    c2 += vi.squaredNorm() / static_cast<double>(n);
  }
  const double scale = std::sqrt(3.0 * T0 / c2);
  const double mass = sphereMass(1.0, 1.91);
  for (std::size_t i = 0; i < centres.size(); ++i) {
    g.particles.addOwned(static_cast<std::int64_t>(i), 0, 0.5, mass, centres[i], scale * v[i], Vec3::Zero(), false);
  }
  return g;
}

// A collision's measured normal restitution and contact time.
struct CollisionResult {
  double restitution;
  double contactTime;
};

// Steps `sim` until gap() closes and opens again; contact start and end are interpolated linearly
// between the steps around each zero crossing of the gap. The restitution is normalSpeed() after
// contact over approachSpeed.
template <class Gap, class Speed>
CollisionResult measureCollision(Simulation& sim, Gap gap, Speed normalSpeed, double approachSpeed) {
  double previousGap = gap();
  double previousTime = sim.time();
  double start = -1.0;
  double end = -1.0;
  while (end < 0.0 && sim.stepCount() < 1000000) {
    sim.step();
    const double g = gap();
    if (start < 0.0 && g < 0.0) start = previousTime + (sim.time() - previousTime) * previousGap / (previousGap - g);
    if (start >= 0.0 && g > 0.0) end = previousTime + (sim.time() - previousTime) * previousGap / (previousGap - g);
    previousGap = g;
    previousTime = sim.time();
  }
  return {normalSpeed() / approachSpeed, end - start};
}

// Granular temperature T = <C^2>/3 (Eq. 5.6) of the owned particles about their mean velocity.
inline double granularTemperature(const Particles& p) {
  Vec3 mean = Vec3::Zero();
  for (std::size_t i = 0; i < p.nOwned; ++i) mean += p.v[i];
  mean /= static_cast<double>(p.nOwned);
  double c2 = 0.0;
  for (std::size_t i = 0; i < p.nOwned; ++i) c2 += (p.v[i] - mean).squaredNorm();
  return c2 / (3.0 * static_cast<double>(p.nOwned));
}

// Elastic energy stored in the contacts of a frame recorded with the linear law (f = 1):
// 1/2 k_n delta^2 + 1/2 k_t |u_t|^2, recovered from the spring forces k_n delta and -k_t u_t.
inline double elasticEnergy(const core::data::ParticleFrame& f, const PairMaterial& m) {
  double e = 0.0;
  for (std::size_t k = 0; k < f.contacts.size(); ++k) {
    e += 0.5 * f.contacts.forceNormalElastic[k].squaredNorm() / m.kn;
    if (m.kt > 0.0) e += 0.5 * f.contacts.forceTangentialElastic[k].squaredNorm() / m.kt;
  }
  return e;
}

// Particles whose id, position, velocity or spin differ in any bit (a and b hold as many): the
// measure of the restart tests.
inline std::size_t differingParticles(const Simulation& a, const Simulation& b) {
  const auto& pa = a.particles();
  const auto& pb = b.particles();
  std::size_t differing = 0;
  for (std::size_t i = 0; i < pa.nOwned; ++i) {
    if (pa.id[i] != pb.id[i] || pa.x[i] != pb.x[i] || pa.v[i] != pb.v[i] || pa.omega[i] != pb.omega[i]) ++differing;
  }
  return differing;
}

}  // namespace grainbridge::dem::testing
