#pragma once
// Builders for TF-DEM tests: a gas grid with its patches, small beds of millimetre glass beads in
// a walled box, and a gas state at rest with its hydrostatic pressure.
#include <cmath>
#include <random>
#include <vector>

#include "engines/dem/Insertion.hpp"
#include "engines/tfdem/TfdemEngine.hpp"

namespace grainbridge::tfdem::testing {

inline core::data::GridGeometry boxGrid(std::array<int, 3> cells, double cell) {
  core::data::GridGeometry g;
  g.cells = cells;
  g.spacing = Vec3::Constant(cell);
  return g;
}

inline Vec3 extent(const core::data::GridGeometry& g) {
  return {g.cells[0] * g.spacing.x(), g.cells[1] * g.spacing.y(), g.cells[2] * g.spacing.z()};
}

// Glass-like beads: a linear spring-dashpot of restitution about 0.9 at these masses.
inline dem::PairMaterial beads() {
  dem::PairMaterial m;
  m.kn = 800.0;
  m.kt = 2.0 / 7.0 * m.kn;
  m.gammaN = 2000.0;
  m.mu = 0.3;
  return m;
}

// The DEM over the gas grid's box with plane walls on every side, gravity along -y.
inline dem::SimulationSetup walledBox(const core::data::GridGeometry& g, double dt) {
  dem::SimulationSetup s;
  s.lo = g.origin;
  s.hi = g.origin + extent(g);
  s.gravity = Vec3(0.0, -9.81, 0.0);
  s.dt = dt;
  s.skin = 2e-4;
  s.species = 1;
  s.pairMaterial.assign(1, beads());
  for (int a = 0; a < 3; ++a) {
    for (int side = 0; side < 2; ++side) {
      dem::Wall w;
      w.kind = dem::Wall::Kind::Plane;
      w.direction = Vec3::Unit(a) * (side == 0 ? 1.0 : -1.0);
      w.origin = side == 0 ? s.lo : s.hi;
      w.material.assign(1, beads());
      s.walls.push_back(w);
    }
  }
  return s;
}

// n beads of diameter d and density rho at random in [lo, hi), at rest.
inline dem::Particles randomBeads(int n, double d, double rho, const Vec3& lo, const Vec3& hi, std::uint64_t seed) {
  dem::InsertionRequest rq;
  rq.lo = lo;
  rq.hi = hi;
  rq.radii.assign(static_cast<std::size_t>(n), 0.5 * d);
  std::mt19937_64 rng(seed);
  const auto centres = dem::insertRandomly(rq, rng);
  dem::Particles p;
  const double m = rho * M_PI / 6.0 * d * d * d;
  for (std::size_t i = 0; i < centres.size(); ++i)
    p.addOwned(static_cast<std::int64_t>(i), 0, 0.5 * d, m, centres[i], Vec3::Zero(), Vec3::Zero(), false);
  return p;
}

// Uniform inflow at the bottom, a pressure outlet on top, free-slip side walls.
inline std::vector<fluid::BoundaryPatch> column(double inflow, int dimensions) {
  fluid::BoundaryPatch inlet;
  inlet.kind = fluid::BoundaryKind::VelocityInlet;
  inlet.side = fluid::YLow;
  inlet.phases = {fluid::PhaseInflow{1.0, Vec3(0.0, inflow, 0.0)}, fluid::PhaseInflow{0.0, Vec3::Zero()}};
  fluid::BoundaryPatch outlet;
  outlet.kind = fluid::BoundaryKind::PressureOutlet;
  outlet.side = fluid::YHigh;
  outlet.pressure = 101325.0;
  outlet.phases = {fluid::PhaseInflow{1.0, Vec3::Zero()}, fluid::PhaseInflow{0.0, Vec3::Zero()}};
  std::vector<fluid::BoundaryPatch> patches{inlet, outlet};
  for (int side : {fluid::XLow, fluid::XHigh, fluid::ZLow, fluid::ZHigh}) {
    if (side >= 2 * dimensions) continue;
    fluid::BoundaryPatch wall;
    wall.kind = fluid::BoundaryKind::FreeSlipWall;
    wall.side = side;
    patches.push_back(wall);
  }
  return patches;
}

// The gas at `inflow` upward everywhere, at the outlet's pressure.
inline fluid::FlowState uniformGas(const fluid::StaggeredGrid& grid, double inflow) {
  fluid::FlowState s(grid, 2);
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    s.phases[0].fraction[c] = 1.0;
    s.phases[0].velocity[1][c] = inflow;
    s.pressure[c] = 101325.0;
  }
  return s;
}

}  // namespace grainbridge::tfdem::testing
