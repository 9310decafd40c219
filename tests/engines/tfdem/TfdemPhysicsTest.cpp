// TF-DEM against what the drag law alone says: a particle falling through still gas (one-way: the
// gas is held) reaches the terminal velocity where the law's drag, with the buoyancy of -V_p grad
// P_g, balances its weight; and gas forced through a fixed packed layer loses the pressure Eq.
// 7.30's Ergun branch gives at the deposited fraction.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engines/closures/MinimumFluidization.hpp"
#include "engines/fluid/BedMeasures.hpp"
#include "engines/fluid/FieldSampling.hpp"
#include "engines/tfdem/ParticleForces.hpp"
#include "tests/engines/tfdem/TfdemTestSupport.hpp"

using namespace grainbridge;
using namespace grainbridge::tfdem;
using namespace grainbridge::tfdem::testing;

namespace {

constexpr double kRhoG = 1.2, kMuG = 1.8e-5, kG = 9.81;

// The slip at which the law's per-particle drag eps_g f_d (Eq. 7.29, beta of Eqs. 7.30-7.31's
// Wen-Yu branch at this dilute fraction) balances the buoyant weight.
double terminalSlip(const closures::GasSolidsDrag& law, double d, double rhoP, double epsS) {
  const double vp = M_PI / 6.0 * d * d * d, weight = (rhoP - kRhoG) * vp * kG;
  double lo = 0.0, hi = 100.0;
  for (int k = 0; k < 200; ++k) {
    const double v = 0.5 * (lo + hi);
    closures::DragState s{1.0 - epsS, epsS, d, kRhoG, kMuG, v};
    ((1.0 - epsS) * law.evaluate(s).particle * v < weight ? lo : hi) = v;
  }
  return 0.5 * (lo + hi);
}

// The 2D bed of the bed tests: beads of 4 mm (Table 7.1's jet material) in an 8 x 24 cm box of
// 1 cm gas cells one diameter deep, plane walls at x and y only (a planar bed needs none at z),
// dt 1.5e-5 s and ten DEM steps per gas step.
constexpr double kBedDiameter = 4e-3, kBedDensity = 2700.0;

TfdemSetup twoDimensionalBed() {
  TfdemSetup setup;
  setup.grid.cells = {8, 24, 1};
  setup.grid.spacing = Vec3(0.01, 0.01, kBedDiameter);
  setup.particles = walledBox(setup.grid, 1.5e-5);
  setup.particles.walls.resize(4);
  setup.particles.planarAxis = 2;
  setup.particles.pairMaterial[0].gammaN = 400.0;  // eta_n 0.018 kg/s at m_eff of two 4 mm beads
  for (auto& w : setup.particles.walls) w.material[0].gammaN = 400.0;
  setup.particles.skin = 1e-3;
  setup.substeps = 10;
  setup.gas = {kRhoG, kMuG};
  setup.solver.gravity = Vec3(0.0, -kG, 0.0);
  return setup;
}

// Uniform inflow at the bottom, a pressure outlet on top, no-slip side walls.
std::vector<fluid::BoundaryPatch> walledColumn(double inflow) {
  auto patches = column(inflow, 2);
  for (std::size_t k = 2; k < patches.size(); ++k) patches[k].kind = fluid::BoundaryKind::NoSlipWall;
  return patches;
}

}  // namespace

TEST(TfdemPhysics, AParticleInStillGasReachesTheLawsTerminalVelocity) {
  const auto g = boxGrid({2, 40, 2}, 1e-2);
  const fluid::StaggeredGrid grid(g);
  const double d = 1e-4, rhoP = 2500.0;
  dem::SimulationSetup setup = walledBox(g, 1e-4);
  setup.walls.clear();
  setup.skin = 1e-2;  // one particle: a coarse neighbour grid
  setup.fluidCoupled = true;  // the buoyancy -V_p grad P_g applies
  dem::Particles p;
  p.addOwned(0, 0, 0.5 * d, rhoP * M_PI / 6.0 * d * d * d, Vec3(0.01, 0.38, 0.01), Vec3::Zero(), Vec3::Zero(),
             false);
  dem::Simulation sim(setup, std::move(p));
  // The gas at rest with its hydrostatic pressure.
  fluid::FlowState gas(grid, 2);
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    const auto [i, j, k] = grid.coordinates(c);
    gas.phases[0].fraction[c] = 1.0;
    gas.pressure[c] = 101325.0 - kRhoG * kG * grid.cellCentre(i, j, k).y();
  }
  const auto law = closures::GasSolidsDrag::byName("ergun_wen_yu");
  ParticleForceSettings settings;
  settings.transfer = DragTransfer::PerParticle;
  settings.gas = {kRhoG, kMuG};
  const std::vector<Vec3> noCellDrag(grid.paddedCount(), Vec3::Zero());
  // 0.3 s: more than 7 relaxation times of this particle (v_t / g = 0.04 s).
  for (int fluidStep = 0; fluidStep < 300; ++fluidStep) {
    const ParticleDeposit dep = depositParticles(grid, sim.particles(), VolumeDeposition::CentreCell);
    for (std::size_t c = 0; c < grid.paddedCount(); ++c) gas.phases[0].fraction[c] = 1.0 - dep.fraction[c];
    setParticleForces(sim.mutableParticles(), gas, dep, noCellDrag, law, settings);
    sim.run(10);
  }
  const double epsS = M_PI / 6.0 * d * d * d / grid.cellVolume();
  const double expected = terminalSlip(law, d, rhoP, epsS);
  EXPECT_GT(expected, 0.3);  // well past Stokes (Re about 2): the law's C_D matters
  EXPECT_NEAR(-sim.particles().v[0].y(), expected, 0.01 * expected);
  std::printf("terminal: %.6g m/s, the law's %.6g m/s\n", -sim.particles().v[0].y(), expected);
  EXPECT_NEAR(sim.particles().v[0].x(), 0.0, 1e-12);
}

// A simple cubic lattice of frozen 2 mm beads at 2.5 mm spacing fills y 2-6 cm: 64 per 1 cm cell,
// eps_s = (pi/6) 0.8^3 = 0.268 in every layer cell (Ergun's branch, eps_g < 0.8). Gas enters at
// 5 cm/s. Inside the layer the flow is uniform, so eps_g dP/dy = -beta v_g (v_s = 0) with
// v_g = U / eps_g and beta of Eq. 7.30's Ergun branch written out here.
TEST(TfdemPhysics, GasThroughAFixedLayerLosesTheErgunPressure) {
  const auto g = boxGrid({2, 10, 2}, 1e-2);
  const double d = 2e-3, spacing = 2.5e-3, U = 0.05;
  dem::Particles p;
  std::int64_t id = 0;
  for (int k = 0; k < 8; ++k) {
    for (int j = 0; j < 16; ++j) {
      for (int i = 0; i < 8; ++i) {
        const Vec3 x((i + 0.5) * spacing, 0.02 + (j + 0.5) * spacing, (k + 0.5) * spacing);
        p.addOwned(id++, 0, 0.5 * d, 2500.0 * M_PI / 6.0 * d * d * d, x, Vec3::Zero(), Vec3::Zero(), true);
      }
    }
  }
  TfdemSetup setup;
  setup.grid = g;
  setup.particles = walledBox(g, 1e-4);
  setup.substeps = 10;
  setup.boundaries = column(U, 3);
  setup.gas = {kRhoG, kMuG};
  setup.solver.gravity = Vec3::Zero();
  setup.solver.tolerance = 1e-10;
  setup.solver.maxIterations = 200;
  const fluid::StaggeredGrid grid(g);
  const auto dir = std::filesystem::temp_directory_path() / "grainbridge-tfdem-ergun";
  std::filesystem::remove_all(dir);
  TfdemEngine engine(setup, std::move(p), uniformGas(grid, U), dir, core::io::ArtifactStamp{"test"});
  for (int step = 0; step < 100; ++step) engine.advance(false);
  const double epsS = M_PI / 6.0 * 0.8 * 0.8 * 0.8, epsG = 1.0 - epsS, vg = U / epsG;
  EXPECT_NEAR(engine.deposit().fraction[grid.index(1, 3, 1)], epsS, 1e-12);
  const double beta = 150.0 * epsS * epsS * kMuG / (epsG * d * d) + 1.75 * epsS * kRhoG * vg / d;
  const double expected = beta * vg / epsG * 0.03;  // from the first layer cell's centre to the last's
  const auto& P = engine.flow().pressure;
  for (int i = 0; i < 2; ++i) {
    for (int k = 0; k < 2; ++k) {
      const double dp = P[grid.index(i, 2, k)] - P[grid.index(i, 5, k)];
      EXPECT_NEAR(dp, expected, 0.01 * expected) << i << " " << k;
      std::printf("fixed layer: dp %.6g Pa, Ergun %.6g Pa\n", dp, expected);
    }
  }
  std::filesystem::remove_all(dir);
}

// A 2D bed (one layer of 300 beads of 4 mm, Table 7.1's jet material, in an 8 x 24 cm box one
// diameter deep) at 1.5 times the drag law's U_mf: fluidized, the gas carries the whole bed, so
// the time-averaged pressure drop across it is its buoyant weight per unit area of the bottom
// (the gas momentum balance of Eq. 7.32 summed over the bed: the drag and -eps_s grad P_g the
// particles feel are what holds them up; U_mf from the law, closures::minimumFluidizationVelocity).
TEST(TfdemPhysics, AFluidizedTwoDimensionalBedIsCarriedByTheGas) {
  const double d = kBedDiameter, rhoP = kBedDensity;
  TfdemSetup setup = twoDimensionalBed();
  const core::data::GridGeometry& g = setup.grid;
  dem::Particles particles = randomBeads(300, d, rhoP, Vec3::Zero(), Vec3(0.08, 0.10, d), 5);
  // U_mf of the drag law at the settled bed's mean fraction: one layer at area fraction about 0.8
  // is eps_s = 0.8 * 2/3 in a slab one diameter deep.
  closures::PackedBed packed;
  packed.voidFraction = 1.0 - 0.8 * 2.0 / 3.0;
  packed.diameter = d;
  packed.solidsDensity = rhoP;
  packed.gasDensity = kRhoG;
  packed.gasViscosity = kMuG;
  const double umf = closures::minimumFluidizationVelocity(setup.drag, packed);
  const double inflow = 1.5 * umf;
  setup.boundaries = walledColumn(inflow);
  const fluid::StaggeredGrid grid(g);
  const auto dir = std::filesystem::temp_directory_path() / "grainbridge-tfdem-bed2d";
  std::filesystem::remove_all(dir);
  TfdemEngine engine(setup, std::move(particles), uniformGas(grid, inflow), dir, core::io::ArtifactStamp{"test"});
  const fluid::VerticalAxis up{1, 1.0};
  const double fluidDt = setup.fluidDt();
  double sum = 0.0;
  int samples = 0;
  const auto steps = static_cast<int>(std::lround(3.0 / fluidDt));
  for (int step = 1; step <= steps; ++step) {
    engine.advance(false);
    if (engine.time() < 1.0) continue;
    // Bottom to top, less the gas column's own weight.
    sum += fluid::pressureAtHeight(engine.flow(), up, 0.0) - fluid::pressureAtHeight(engine.flow(), up, 0.24) -
           kRhoG * kG * 0.24;
    ++samples;
  }
  double weight = 0.0;
  const auto& p = engine.simulation().particles();
  for (std::size_t i = 0; i < p.nOwned; ++i) weight += p.mass[i] * (1.0 - kRhoG / rhoP) * kG;
  const double perArea = weight / (0.08 * d), mean = sum / samples;
  std::printf("2D bed at %.3f m/s (U_mf %.3f): mean dp %.2f Pa, buoyant weight %.2f Pa\n", inflow, umf, mean, perArea);
  EXPECT_NEAR(mean, perArea, 0.03 * perArea);
  // Carried, not pinned against the top wall (which would carry weight of its own).
  double height = 0.0;
  for (std::size_t i = 0; i < p.nOwned; ++i) height += p.x[i].y() / static_cast<double>(p.nOwned);
  EXPECT_LT(height, 0.12);
  std::filesystem::remove_all(dir);
}

// U_mf from an inflow ramp, as a fluidization curve is measured: the same 2D bed as above settled
// without the gas, then the inflow raised step by step. Below U_mf the layer stays packed and
// its drop follows the drag law's Ergun branch (Eq. 7.30), a U + b U^2 (fitted to three steps); above it the
// drop is the bed's weight (the mean over two steps). Where the two meet is the measured U_mf; the
// drag law's own (closures::minimumFluidizationVelocity) at the settled bed's mean fraction, its
// particle volume over the box's width and depth times its height (twice the mean particle
// height), must be within 10 %.
TEST(TfdemPhysics, AnInflowRampFindsTheLawsMinimumFluidizationVelocity) {
  const double d = kBedDiameter, rhoP = kBedDensity, height = 0.24, width = 0.08;
  TfdemSetup setup = twoDimensionalBed();
  const core::data::GridGeometry& g = setup.grid;
  auto patchesAt = [](double inflow) { return walledColumn(inflow); };
  setup.boundaries = patchesAt(0.0);
  const fluid::StaggeredGrid grid(g);
  const auto dir = std::filesystem::temp_directory_path() / "grainbridge-tfdem-ramp";
  std::filesystem::remove_all(dir);
  TfdemEngine engine(setup, randomBeads(300, d, rhoP, Vec3::Zero(), Vec3(width, 0.10, d), 5), uniformGas(grid, 0.0),
                     dir, core::io::ArtifactStamp{"test"});
  const double fluidDt = setup.fluidDt();
  auto run = [&](double seconds) {
    for (int s = 0; s < static_cast<int>(std::lround(seconds / fluidDt)); ++s) engine.advance(false);
  };
  engine.setGasActive(false);
  run(0.5);
  engine.setGasActive(true);

  // The settled bed and the law's U_mf at its mean fraction.
  const auto& p = engine.simulation().particles();
  double volume = 0.0, weight = 0.0, meanHeight = 0.0;
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    volume += particleVolume(p.radius[i]);
    weight += p.mass[i] * (1.0 - kRhoG / rhoP) * kG;
    meanHeight += p.x[i].y() / static_cast<double>(p.nOwned);
  }
  closures::PackedBed packed;
  packed.voidFraction = 1.0 - volume / (width * d * 2.0 * meanHeight);
  packed.diameter = d;
  packed.solidsDensity = rhoP;
  packed.gasDensity = kRhoG;
  packed.gasViscosity = kMuG;
  const double predicted = closures::minimumFluidizationVelocity(setup.drag, packed);

  const fluid::VerticalAxis up{1, 1.0};
  auto meanDrop = [&](double settle, double seconds) {
    run(settle);
    double sum = 0.0;
    int n = 0;
    for (int s = 0; s < static_cast<int>(std::lround(seconds / fluidDt)); ++s) {
      engine.advance(false);
      sum += fluid::pressureAtHeight(engine.flow(), up, 0.0) - fluid::pressureAtHeight(engine.flow(), up, height) -
             kRhoG * kG * height;
      ++n;
    }
    return sum / n;
  };
  // The packed branch: a U + b U^2 through three steps, least squares.
  double s2 = 0.0, s3 = 0.0, s4 = 0.0, sy1 = 0.0, sy2 = 0.0;
  for (double f : {0.3, 0.5, 0.7}) {
    const double u = f * predicted;
    engine.setPatches(patchesAt(u));
    const double dp = meanDrop(0.05, 0.05);
    std::printf("ramp: U = %.3f m/s, dp = %.1f Pa\n", u, dp);
    s2 += u * u;
    s3 += u * u * u;
    s4 += u * u * u * u;
    sy1 += u * dp;
    sy2 += u * u * dp;
  }
  const double det = s2 * s4 - s3 * s3;
  const double a = (sy1 * s4 - sy2 * s3) / det, b = (s2 * sy2 - s3 * sy1) / det;
  // The plateau: fluidized, the drop is the bed's weight per area.
  double plateau = 0.0;
  for (double f : {1.4, 1.7}) {
    engine.setPatches(patchesAt(f * predicted));
    const double dp = meanDrop(0.3, 0.7);
    std::printf("ramp: U = %.3f m/s, dp = %.1f Pa\n", f * predicted, dp);
    plateau += 0.5 * dp;
  }
  const double measured = (-a + std::sqrt(a * a + 4.0 * b * plateau)) / (2.0 * b);
  std::printf("U_mf: measured %.4f m/s, drag law at eps_g %.4f: %.4f m/s; plateau %.1f Pa, weight %.1f Pa\n", measured,
              packed.voidFraction, predicted, plateau, weight / (width * d));
  EXPECT_NEAR(measured, predicted, 0.10 * predicted);
  EXPECT_NEAR(plateau, weight / (width * d), 0.05 * weight / (width * d));
  std::filesystem::remove_all(dir);
}
