#pragma once
// The grain bed of the reference's Tables 4.1-4.3 on a small grid for tests: cells of 0.9525 cm,
// 2.3 mm grains of 1491.8 kg/m^3 (VALIDATION.md), a bed of `bedCells` rows at eps_g 0.404, air
// entering uniformly through the bottom, the top at 101325 Pa, free-slip side walls (so the bed's
// weight rests on the gas and the bottom alone, and the pressure drop is the weight's).
#include <memory>

#include "engines/mfm/MultiFluidEngine.hpp"

namespace grainbridge::testing {

struct GrainBedSpec {
  int nx = 2;
  int ny = 16;
  int nz = 1;  // > 1: a 3D grid, free-slip walls at z too
  int bedCells = 8;
  double cell = 0.009525;               // [m]
  double voidFraction = 0.404;          // the bed's initial eps_g
  double criticalVoidFraction = 0.404;  // eps_g* of the plastic regime
  double inflow = 0.3;                  // superficial gas velocity U [m/s]
  double c = 0.8, d = 2.65;             // Syamlal-O'Brien (Table 4.3, CFD 1)
  bool inletAndOutlet = true;           // false: a closed box
  double maxDt = 1e-3;
  // Relative amplitude of a fixed pseudo-random perturbation of the bed's solids fraction: a
  // perfectly uniform bed between free-slip walls stays one-dimensional and slugs as a piston.
  double perturbation = 0.0;
};

inline constexpr double kGrainDiameter = 2.3e-3, kGrainDensity = 1491.8, kAirDensity = 1.2, kAirViscosity = 1.8e-5;
inline constexpr double kOutletPressure = 101325.0, kGravity = 9.81;

inline std::unique_ptr<mfm::MultiFluidEngine> makeGrainBed(const GrainBedSpec& s) {
  core::data::GridGeometry g;
  g.cells = {s.nx, s.ny, s.nz};
  g.spacing = Vec3(s.cell, s.cell, s.cell);
  g.origin = Vec3::Zero();
  std::vector<fluid::BoundaryPatch> patches;
  std::vector<int> walls{fluid::XLow, fluid::XHigh};
  if (s.nz > 1) walls.insert(walls.end(), {fluid::ZLow, fluid::ZHigh});
  for (int side : walls) {
    fluid::BoundaryPatch wall;
    wall.kind = fluid::BoundaryKind::FreeSlipWall;
    wall.side = side;
    patches.push_back(wall);
  }
  if (s.inletAndOutlet) {
    fluid::BoundaryPatch inlet;
    inlet.kind = fluid::BoundaryKind::VelocityInlet;
    inlet.side = fluid::YLow;
    inlet.phases = {fluid::PhaseInflow{1.0, Vec3(0.0, s.inflow, 0.0)}, fluid::PhaseInflow{0.0, Vec3::Zero()}};
    fluid::BoundaryPatch outlet;
    outlet.kind = fluid::BoundaryKind::PressureOutlet;
    outlet.side = fluid::YHigh;
    outlet.pressure = kOutletPressure;
    patches.push_back(inlet);
    patches.push_back(outlet);
  }
  mfm::MultiFluidParams model;
  model.gas = {kAirDensity, kAirViscosity};
  model.solids = {mfm::SolidsPhase{"grain", kGrainDiameter, kGrainDensity, 0.9}};
  model.drag = closures::GasSolidsDrag::byName("syamlal_obrien");
  std::get<closures::SyamlalOBrien>(model.drag.law).params = {s.c, s.d};
  model.plastic.params.criticalVoidFraction = s.criticalVoidFraction;
  fluid::SimpleSettings settings;
  settings.gravity = Vec3(0.0, -kGravity, 0.0);
  settings.packedFraction = 1.0 - s.criticalVoidFraction;
  fluid::TimeStepLimits limits;
  limits.initial = 1e-4;
  limits.maximum = s.maxDt;
  auto engine = std::make_unique<mfm::MultiFluidEngine>(g, patches, model, settings, limits);

  // Bed below, freeboard above; the gas at U / eps_g; the pressure at the weight of what lies above.
  fluid::FlowState& st = engine->state();
  const auto& grid = engine->grid();
  const double solids = 1.0 - s.voidFraction;
  unsigned state = 12345u;
  for (int j = s.ny - 1; j >= 0; --j) {
    for (int i = 0; i < s.nx * s.nz; ++i) {
      const std::size_t c = grid.index(i % s.nx, j, i / s.nx);
      const bool bed = j < s.bedCells;
      state = state * 1664525u + 1013904223u;  // a fixed linear congruential sequence
      const double noise = (static_cast<double>(state >> 8) / static_cast<double>(1u << 24)) * 2.0 - 1.0;
      st.phases[1].fraction[c] = bed ? solids * (1.0 - s.perturbation * (0.5 + 0.5 * noise)) : 0.0;
      st.phases[0].fraction[c] = 1.0 - st.phases[1].fraction[c];
      st.phases[0].velocity[1][c] = s.inletAndOutlet ? s.inflow / (bed ? s.voidFraction : 1.0) : 0.0;
      const double above = j + 1 < s.ny ? st.pressure(i % s.nx, j + 1, i / s.nx) : kOutletPressure;
      const double weight = ((bed ? solids * kGrainDensity : 0.0) + kAirDensity) * kGravity * s.cell;
      st.pressure[c] = above + (j + 1 < s.ny ? weight : 0.5 * weight);
    }
  }
  return engine;
}

}  // namespace grainbridge::testing
