// The granular-energy equation of the multi-fluid model (Eq. 3.34, issue 18):
//   - a uniform cell of grains at rest, without gas, cools as Haff's law says with Eq. 5.7's
//     dissipation (the figure the DEM reproduces for the same grains);
//   - theta stays non-negative in a bed that collapses from a fluidized-like state to packing;
//   - the rotation model changes the collisional and wall dissipation and nothing else;
//   - a resumed pde run repeats the uninterrupted one bit for bit (theta travels in the
//     checkpoint).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engines/closures/RadialDistribution.hpp"
#include "engines/mfm/InitialRegions.hpp"
#include "engines/mfm/MfmEngine.hpp"
#include "tests/engines/mfm/GrainBed.hpp"
#include "tests/support/TempDir.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;

namespace {

constexpr double kDiameter = 1e-3, kDensity = 2500.0, kRestitution = 0.9;

// Grains at rest filling a closed 3 x 3 box at solid fraction eps and temperature theta0, no
// gravity; the gas terms off, so only the collisional dissipation acts.
std::unique_ptr<mfm::MultiFluidEngine> coolingCell(double eps, double theta0, double dt) {
  core::data::GridGeometry g;
  g.cells = {3, 3, 1};
  g.spacing = Vec3(0.01, 0.01, 0.01);
  g.origin = Vec3::Zero();
  mfm::MultiFluidParams model;
  model.solids = {mfm::SolidsPhase{"grains", kDiameter, kDensity, kRestitution}};
  model.granularGasCoupling = false;
  model.plastic.params.criticalVoidFraction = 0.4;
  fluid::SimpleSettings settings;
  settings.packedFraction = 0.6;
  fluid::TimeStepLimits limits;
  limits.initial = dt;
  limits.minimum = dt;
  limits.maximum = dt;
  auto engine = std::make_unique<mfm::MultiFluidEngine>(g, std::vector<fluid::BoundaryPatch>{}, model, settings, limits);
  mfm::InitialState initial;
  mfm::InitialRegion all;
  all.lo = Vec3(0.0, 0.0, 0.0);
  all.hi = Vec3(0.03, 0.03, 0.01);
  all.solidsFractions = {eps};
  all.velocities = {Vec3::Zero(), Vec3::Zero()};
  all.granularTemperature = theta0;
  initial.regions = {all};
  mfm::initialise(*engine, initial);
  return engine;
}

// The grain bed with Chapter 5's model instead of Chapter 4's: Lun et al. with the
// granular-energy equation, Johnson-Jackson walls (phi' 0.6), every region at theta0.
GrainBed kineticTheoryBed(const GrainBedSpec& spec, double theta0) {
  GrainBed bed = grainBed(spec);
  auto& model = bed.setup.model;
  model.granularEnergy = mfm::GranularEnergyForm::Pde;
  model.closure = closures::ClosureModel::kineticTheory();
  model.wall = closures::JohnsonJackson::Params{0.6, 1.0 - spec.criticalVoidFraction, 1.0, {}};
  for (auto& r : bed.initial.regions) r.granularTemperature = theta0;
  return bed;
}

}  // namespace

TEST(GranularEnergy, AUniformCellCoolsAsHaffsLawSays) {
  const double eps = 0.3, theta0 = 0.01, dt = 2e-5;
  auto cell = coolingCell(eps, theta0, dt);
  // 3/2 rho eps dtheta/dt = -J (Eq. 5.7): dtheta/dt = -A theta^(3/2) with
  // A = 8 (1 - e^2) eps g0 / (sqrt(pi) d), so theta = theta0 / (1 + A sqrt(theta0) t / 2)^2.
  const double g0 = closures::carnahanStarlingG0(eps);
  const double A = 8.0 * (1.0 - kRestitution * kRestitution) * eps * g0 / (std::sqrt(std::numbers::pi) * kDiameter);
  const double tau = 2.0 / (A * std::sqrt(theta0));  // theta falls to a quarter at t = tau
  cell->advanceTo(tau);
  const double haff = theta0 / std::pow(1.0 + A * std::sqrt(theta0) * cell->time() / 2.0, 2);
  const auto& st = cell->state();
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      const std::size_t c = cell->grid().index(i, j, 0);
      // First-order implicit steps of dt / tau = 6e-4 lag the exact decay by about that much.
      EXPECT_NEAR(st.phases[1].granularTemperature[c], haff, 2e-3 * haff) << "cell " << i << ", " << j;
      EXPECT_NEAR(st.phases[1].fraction[c], eps, 1e-12);
    }
  }
  EXPECT_NEAR(haff, theta0 / 4.0, 1e-3 * theta0);
}

TEST(GranularEnergy, TemperatureStaysNonNegativeInABedThatCollapses) {
  // A loose, agitated bed (eps_s 0.45, theta 0.05 m^2/s^2) on a gas flow at a third of its
  // minimum fluidization: it falls onto the bottom and packs, and its fluctuations die out.
  GrainBedSpec spec;
  spec.nx = 4;
  spec.ny = 12;
  spec.bedCells = 8;
  spec.voidFraction = 0.55;
  spec.inflow = 0.25;
  spec.perturbation = 0.05;
  GrainBed bed = kineticTheoryBed(spec, 0.05);
  for (auto& p : bed.setup.patches) {
    if (p.kind == fluid::BoundaryKind::FreeSlipWall) p.kind = fluid::BoundaryKind::NoSlipWall;
  }
  mfm::MultiFluidEngine engine(bed.setup.geometry, bed.setup.patches, bed.setup.model, bed.setup.settings,
                               bed.setup.limits);
  mfm::initialise(engine, bed.initial);
  for (int k = 1; k <= 20; ++k) {
    engine.advanceTo(0.025 * k);
    double coldest = 1.0;
    for (double theta : engine.state().phases[1].granularTemperature.values()) coldest = std::min(coldest, theta);
    ASSERT_GE(coldest, 0.0) << "at t = " << engine.time();
  }
  // After 0.5 s the bed is packed (eps_s 0.603) below its surface row, where the gas's slip
  // keeps the grains agitated; inside it the fluctuations have died out (measured: 3.8e-4 m^2/s^2
  // just under the surface, 1e-5 in the lower half, from 0.05).
  const auto& grid = engine.grid();
  const auto& solids = engine.state().phases[1];
  int packed = 0;
  for (int j = 0; j < grid.cells(1); ++j) {
    for (int i = 0; i < grid.cells(0); ++i) {
      const std::size_t c = grid.index(i, j, 0);
      if (solids.fraction[c] < 0.59) continue;
      ++packed;
      EXPECT_LT(solids.granularTemperature[c], 0.01 * 0.05) << "cell " << i << ", " << j;
      if (j < grid.cells(1) / 4) {
        EXPECT_LT(solids.granularTemperature[c], 1e-3 * 0.05) << "cell " << i << ", " << j;
      }
    }
  }
  EXPECT_GE(packed, 4 * 4) << "the bed should have packed";
}

// plastic_theta pinned (MFIX's Schaeffer branch of solve_granular_energy.f): in every cell packed
// beyond the plastic onset, eps_g < eps_g*, theta is pinnedTheta after each step, while the cells
// above the packing keep a solved theta; solved, the same bed keeps fluctuations in its packed cells.
TEST(GranularEnergy, PinnedPlasticThetaHoldsThePackedCellsAtTheSmallTheta) {
  GrainBedSpec spec;
  spec.nx = 4;
  spec.ny = 12;
  spec.bedCells = 8;
  spec.voidFraction = 0.55;
  spec.inflow = 0.25;
  spec.perturbation = 0.05;
  auto run = [&](mfm::PlasticTheta mode) {
    GrainBed bed = kineticTheoryBed(spec, 0.05);
    bed.setup.model.plasticTheta = mode;
    auto engine = std::make_unique<mfm::MultiFluidEngine>(bed.setup.geometry, bed.setup.patches, bed.setup.model,
                                                          bed.setup.settings, bed.setup.limits);
    mfm::initialise(*engine, bed.initial);
    engine->advanceTo(0.3);
    return engine;
  };
  const auto pinned = run(mfm::PlasticTheta::Pinned);
  const auto solved = run(mfm::PlasticTheta::Solved);
  const double small = mfm::MultiFluidParams{}.pinnedTheta;
  int plasticCells = 0, solvedAbove = 0, solvedWarmer = 0;
  const auto& grid = pinned->grid();
  for (int j = 0; j < grid.cells(1); ++j) {
    for (int i = 0; i < grid.cells(0); ++i) {
      const std::size_t c = grid.index(i, j, 0);
      const auto& phase = pinned->state().phases[1];
      if (1.0 - phase.fraction[c] < spec.criticalVoidFraction) {
        ++plasticCells;
        EXPECT_EQ(phase.granularTemperature[c], small) << "cell " << i << ", " << j;
      } else if (phase.fraction[c] > 1e-3 && phase.granularTemperature[c] > 10.0 * small) {
        ++solvedAbove;
      }
      const auto& other = solved->state().phases[1];
      if (1.0 - other.fraction[c] < spec.criticalVoidFraction && other.granularTemperature[c] > 10.0 * small)
        ++solvedWarmer;
    }
  }
  EXPECT_GE(plasticCells, 4) << "the bed should have packed beyond eps_g*";
  EXPECT_GE(solvedAbove, 1) << "the cells above the packing still solve for theta";
  EXPECT_GE(solvedWarmer, 1) << "solved, some packed cell keeps a theta above the pinned one";
}

TEST(GranularEnergy, TheRotationModelChangesTheDissipationAndNothingElse) {
  GrainBedSpec spec;
  spec.nx = 4;
  spec.voidFraction = 0.6;
  spec.perturbation = 0.1;
  GrainBed bed = kineticTheoryBed(spec, 0.02);
  auto& model = bed.setup.model;
  model.solids[0].restitution = 0.97;
  model.solids[0].wallRestitution = 0.97;
  model.solids[0].friction = 0.10;  // Table 5.1, large particles
  model.solids[0].wallFriction = 0.09;
  mfm::MultiFluidParams rotating = model;
  rotating.rotation = true;
  const mfm::MultiFluidModel plain(model), rotation(rotating);

  // Eqs. 5.19-5.21: e_eff 0.86206 and e_w,eff 0.87010 (VALIDATION.md), in (1 + e)(1 - e_eff).
  EXPECT_NEAR(rotation.dissipationScale(1), (1.97 * (1.0 - 0.86206)) / (1.0 - 0.97 * 0.97), 2e-4);
  EXPECT_NEAR(*rotation.wallEffectiveRestitution(1), 0.87010, 1e-4);
  EXPECT_EQ(plain.dissipationScale(1), 1.0);
  EXPECT_FALSE(plain.wallEffectiveRestitution(1).has_value());

  mfm::MultiFluidEngine engine(bed.setup.geometry, bed.setup.patches, model, bed.setup.settings, bed.setup.limits);
  mfm::initialise(engine, bed.initial);
  const fluid::FlowState& st = engine.state();
  fluid::FlowProperties a, b;
  for (std::size_t m = 0; m < 2; ++m) {
    a.phases.emplace_back(engine.grid());
    b.phases.emplace_back(engine.grid());
    a.dragCoefficient.emplace_back(engine.grid());
    b.dragCoefficient.emplace_back(engine.grid());
  }
  plain.evaluate(st, a);
  rotation.evaluate(st, b);
  for (std::size_t m = 0; m < 2; ++m) {
    EXPECT_EQ(a.phases[m].solidsPressure.values(), b.phases[m].solidsPressure.values());
    EXPECT_EQ(a.phases[m].shearViscosity.values(), b.phases[m].shearViscosity.values());
    EXPECT_EQ(a.phases[m].bulkViscosity.values(), b.phases[m].bulkViscosity.values());
    EXPECT_EQ(a.phases[m].solidsPressureSlope.values(), b.phases[m].solidsPressureSlope.values());
    EXPECT_EQ(a.phases[m].wallSlipCoefficient.values(), b.phases[m].wallSlipCoefficient.values());
    EXPECT_EQ(a.dragCoefficient[m].values(), b.dragCoefficient[m].values());
  }
  // The wall: the same slip coefficient, the dissipation by (1 + e_w)(1 - e_w,eff) / (1 - e_w^2).
  closures::JohnsonJackson jj{*model.wall};
  jj.params.wallRestitution = 0.97;
  closures::JohnsonJackson jjRotating = jj;
  jjRotating.params.wallEffectiveRestitution = *rotation.wallEffectiveRestitution(1);
  const closures::JohnsonJackson::State ws{0.5, 2526.0, 3.0, 0.01, 0.2};
  EXPECT_EQ(jj.evaluate(ws).slipCoefficient, jjRotating.evaluate(ws).slipCoefficient);
  EXPECT_NEAR(jjRotating.evaluate(ws).wallDissipation / jj.evaluate(ws).wallDissipation,
              1.97 * (1.0 - 0.87010) / (1.0 - 0.97 * 0.97), 1e-3);
}

TEST(GranularEnergy, AResumedRunRepeatsTheUninterruptedOneBitForBit) {
  TempDir dir;
  GrainBedSpec spec;
  spec.nx = 4;
  spec.inflow = 1.2;
  spec.perturbation = 0.02;
  GrainBed bed = kineticTheoryBed(spec, 0.0);
  bed.setup.interval = 0.01;
  const auto initial = [&bed](mfm::MultiFluidEngine& e) { mfm::initialise(e, bed.initial); };
  const core::io::ArtifactStamp stamp{"test"};
  mfm::MfmEngine straight(bed.setup, initial, dir.path() / "a", stamp);
  for (int s = 0; s < 10; ++s) straight.advance(false);
  mfm::MfmEngine first(bed.setup, initial, dir.path() / "b", stamp);
  for (int s = 0; s < 5; ++s) first.advance(false);
  first.saveState(dir.path() / "state.h5", "fp");
  auto resumed = mfm::MfmEngine::restore(bed.setup, dir.path() / "state.h5", "fp", dir.path() / "c", stamp);
  for (int s = 0; s < 5; ++s) resumed->advance(false);
  const auto& x = straight.engine().state();
  const auto& y = resumed->engine().state();
  EXPECT_EQ(x.time, y.time);
  EXPECT_EQ(x.pressure.values(), y.pressure.values());
  EXPECT_EQ(x.phases[1].fraction.values(), y.phases[1].fraction.values());
  EXPECT_EQ(x.phases[1].granularTemperature.values(), y.phases[1].granularTemperature.values());
  double hottest = 0.0;
  for (double theta : x.phases[1].granularTemperature.values()) hottest = std::max(hottest, theta);
  EXPECT_GT(hottest, 0.0) << "the fluidized bed should have generated granular temperature";
}
