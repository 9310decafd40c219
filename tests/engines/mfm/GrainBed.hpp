#pragma once
// The grain bed of the reference's Tables 4.1-4.3 on a small grid for tests: cells of 0.9525 cm,
// 2.3 mm grains of 1491.8 kg/m^3 (VALIDATION.md), a bed of `bedCells` rows at eps_g 0.404, air
// entering uniformly through the bottom, the top at 101325 Pa, free-slip side walls (so the bed's
// weight rests on the gas and the bottom alone, and the pressure drop is the weight's).
#include <memory>

#include "engines/mfm/InitialRegions.hpp"
#include "engines/mfm/MfmEngine.hpp"
#include "engines/mfm/SolidsPairs.hpp"

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
  double maxDt = 1e-3;
  // Relative amplitude of a fixed pseudo-random perturbation of the bed's solids fraction: a
  // perfectly uniform bed between free-slip walls stays one-dimensional and slugs as a piston.
  double perturbation = 0.0;
};

inline constexpr double kGrainDiameter = 2.3e-3, kGrainDensity = 1491.8, kAirDensity = 1.2, kAirViscosity = 1.8e-5;
inline constexpr double kOutletPressure = 101325.0, kGravity = 9.81;

// The engine's setup and the bed's initial state (mfm::initialise: bed and freeboard regions,
// the gas at U / eps_g, the pressure carrying the weight above).
struct GrainBed {
  mfm::MultiFluidSetup setup;
  mfm::InitialState initial;
};

inline GrainBed grainBed(const GrainBedSpec& s) {
  GrainBed bed;
  auto& g = bed.setup.geometry;
  g.cells = {s.nx, s.ny, s.nz};
  g.spacing = Vec3(s.cell, s.cell, s.cell);
  g.origin = Vec3::Zero();
  std::vector<int> walls{fluid::XLow, fluid::XHigh};
  if (s.nz > 1) walls.insert(walls.end(), {fluid::ZLow, fluid::ZHigh});
  for (int side : walls) {
    fluid::BoundaryPatch wall;
    wall.kind = fluid::BoundaryKind::FreeSlipWall;
    wall.side = side;
    bed.setup.patches.push_back(wall);
  }
  fluid::BoundaryPatch inlet;
  inlet.kind = fluid::BoundaryKind::VelocityInlet;
  inlet.side = fluid::YLow;
  inlet.phases = {fluid::PhaseInflow{1.0, Vec3(0.0, s.inflow, 0.0)}, fluid::PhaseInflow{0.0, Vec3::Zero()}};
  fluid::BoundaryPatch outlet;
  outlet.kind = fluid::BoundaryKind::PressureOutlet;
  outlet.side = fluid::YHigh;
  outlet.pressure = kOutletPressure;
  bed.setup.patches.push_back(inlet);
  bed.setup.patches.push_back(outlet);

  auto& model = bed.setup.model;
  model.gas.density = kAirDensity;
  model.gas.viscosity = kAirViscosity;
  model.solids = {mfm::SolidsPhase{"grain", kGrainDiameter, kGrainDensity, 0.9}};
  // Chapter 4's model: Eqs. 3.21-3.25 with the algebraic granular temperature.
  model.granularEnergy = mfm::GranularEnergyForm::Algebraic;
  model.closure = closures::ClosureModel::kineticTheory(closures::KineticModelName::SyamlalAlgebraicPrinted);
  model.drag = closures::GasSolidsDrag::byName("syamlal_obrien");
  std::get<closures::SyamlalOBrien>(model.drag.law).params = {s.c, s.d};
  model.plastic.params.criticalVoidFraction = s.criticalVoidFraction;
  bed.setup.settings.gravity = Vec3(0.0, -kGravity, 0.0);
  bed.setup.settings.packedFraction = 1.0 - s.criticalVoidFraction;
  bed.setup.limits.initial = 1e-4;
  bed.setup.limits.maximum = s.maxDt;

  const Vec3 top(s.nx * s.cell, s.ny * s.cell, s.nz * s.cell);
  const double bedTop = s.bedCells * s.cell;
  bed.initial.regions = {{Vec3::Zero(),
                          Vec3(top.x(), bedTop, top.z()),
                          {1.0 - s.voidFraction},
                          {Vec3(0.0, s.inflow / s.voidFraction, 0.0), Vec3::Zero()}},
                         {Vec3(0.0, bedTop, 0.0), top, {0.0}, {Vec3(0.0, s.inflow, 0.0), Vec3::Zero()}}};
  bed.initial.referencePressure = kOutletPressure;
  bed.initial.perturbation = s.perturbation;
  return bed;
}

// The same bed as a binary mixture: half its solids volume a second, smaller grain (1.6 mm, same
// density), every region's fraction split evenly, Lebowitz's g0 and Eq. 3.18's drag between them.
inline GrainBed binaryGrainBed(const GrainBedSpec& s) {
  GrainBed bed = grainBed(s);
  auto& model = bed.setup.model;
  model.solids.insert(model.solids.begin(), mfm::SolidsPhase{"small", 1.6e-3, kGrainDensity, 0.9});
  model.radialDistribution = mfm::RadialDistributionModel::Lebowitz;
  model.solidsPairs = mfm::solidsPairsFor(model.solids, {}).pairs;
  for (auto& patch : bed.setup.patches) {
    if (!patch.phases.empty()) patch.phases.push_back(fluid::PhaseInflow{0.0, Vec3::Zero()});
  }
  for (auto& region : bed.initial.regions) {
    const double eps = region.solidsFractions.at(0);
    region.solidsFractions = {eps / 2.0, eps / 2.0};
    region.velocities.push_back(Vec3::Zero());
  }
  return bed;
}

inline std::unique_ptr<mfm::MultiFluidEngine> makeGrainBed(const GrainBedSpec& s) {
  const GrainBed bed = grainBed(s);
  const auto& e = bed.setup;
  auto engine = std::make_unique<mfm::MultiFluidEngine>(e.geometry, e.patches, e.model, e.settings, e.limits);
  mfm::initialise(*engine, bed.initial);
  return engine;
}

}  // namespace grainbridge::testing
