// The TF-DEM step's bookkeeping: per cell and gas step, the momentum the particles received from
// the drag is what the gas gave (cell_average: in the same step; summed: the gas takes it back in
// the next), and a run resumed from its checkpoint continues bit for bit.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/engines/tfdem/TfdemTestSupport.hpp"

using namespace grainbridge;
using namespace grainbridge::tfdem;
using namespace grainbridge::tfdem::testing;

namespace {

// 300 beads of 1 mm in a 1.5 x 3 x 1.5 cm box of 5 mm cells, gas in at 1 m/s (well above U_mf).
TfdemSetup smallBed(DragTransfer transfer, GasReaction reaction, VolumeDeposition deposition) {
  TfdemSetup s;
  s.grid = boxGrid({3, 6, 3}, 5e-3);
  s.particles = walledBox(s.grid, 2e-6);
  s.substeps = 25;
  s.boundaries = column(1.0, 3);
  s.gas = {1.2, 1.8e-5};
  s.solver.gravity = Vec3(0.0, -9.81, 0.0);
  s.deposition = deposition;
  s.gasReaction = reaction;
  s.forces.transfer = transfer;
  return s;
}

dem::Particles smallBedParticles() {
  return randomBeads(300, 1e-3, 2500.0, Vec3::Constant(5e-4), Vec3(0.0145, 0.012, 0.0145), 11);
}

struct Scratch {
  std::filesystem::path dir;
  explicit Scratch(const std::string& name) : dir(std::filesystem::temp_directory_path() / name) {
    std::filesystem::remove_all(dir);
  }
  ~Scratch() { std::filesystem::remove_all(dir); }
};

double largest(const std::vector<Vec3>& v) {
  double m = 0.0;
  for (const Vec3& x : v) m = std::max(m, x.norm());
  return m;
}

void expectBalanced(const std::vector<Vec3>& particles, const std::vector<Vec3>& gas) {
  const double scale = std::max(largest(particles), largest(gas));
  ASSERT_GT(scale, 0.0);
  for (std::size_t c = 0; c < particles.size(); ++c)
    EXPECT_LE((particles[c] + gas[c]).norm(), 1e-12 * scale) << "cell " << c;
}

}  // namespace

TEST(TfdemEngine, CellAverageDragGivesTheParticlesWhatTheGasGaveInEachCell) {
  for (auto deposition : {VolumeDeposition::CentreCell, VolumeDeposition::ExactOverlap}) {
    Scratch scratch("grainbridge-tfdem-balance");
    const TfdemSetup setup = smallBed(DragTransfer::CellAverage, GasReaction::CellAverage, deposition);
    const fluid::StaggeredGrid grid(setup.grid);
    TfdemEngine e(setup, smallBedParticles(), uniformGas(grid, 1.0), scratch.dir, core::io::ArtifactStamp{"test"});
    for (int step = 0; step < 4; ++step) {
      e.advance(false);
      expectBalanced(e.particleDragImpulse(), e.gasDragImpulse());
    }
  }
}

TEST(TfdemEngine, TheSummedReactionHandsTheGasTheParticlesDragOfTheLastStep) {
  Scratch scratch("grainbridge-tfdem-summed");
  const TfdemSetup setup = smallBed(DragTransfer::PerParticle, GasReaction::Summed, VolumeDeposition::CentreCell);
  const fluid::StaggeredGrid grid(setup.grid);
  TfdemEngine e(setup, smallBedParticles(), uniformGas(grid, 1.0), scratch.dir, core::io::ArtifactStamp{"test"});
  e.advance(false);
  for (int step = 0; step < 3; ++step) {
    const std::vector<Vec3> received = e.particleDragImpulse();
    e.advance(false);
    expectBalanced(received, e.gasDragImpulse());
  }
}

TEST(TfdemEngine, AResumedRunContinuesBitForBit) {
  Scratch scratch("grainbridge-tfdem-resume");
  const TfdemSetup setup = smallBed(DragTransfer::PerParticle, GasReaction::Summed, VolumeDeposition::ExactOverlap);
  const fluid::StaggeredGrid grid(setup.grid);
  TfdemEngine straight(setup, smallBedParticles(), uniformGas(grid, 1.0), scratch.dir / "a",
                       core::io::ArtifactStamp{"test"});
  TfdemEngine first(setup, smallBedParticles(), uniformGas(grid, 1.0), scratch.dir / "b",
                    core::io::ArtifactStamp{"test"});
  for (int step = 0; step < 3; ++step) {
    straight.advance(false);
    first.advance(false);
  }
  first.saveState(scratch.dir / "state.h5", "key");
  EXPECT_THROW((void)TfdemEngine::restore(setup, scratch.dir / "state.h5", "other", scratch.dir / "c",
                                          core::io::ArtifactStamp{"test"}),
               Error);
  auto resumed =
      TfdemEngine::restore(setup, scratch.dir / "state.h5", "key", scratch.dir / "c", core::io::ArtifactStamp{"test"});
  for (int step = 0; step < 3; ++step) {
    straight.advance(step == 2);
    resumed->advance(step == 2);
  }
  EXPECT_EQ(resumed->time(), straight.time());
  EXPECT_EQ(resumed->step(), straight.step());
  EXPECT_EQ(resumed->flow().pressure.values(), straight.flow().pressure.values());
  EXPECT_EQ(resumed->flow().phases[0].velocity[1].values(), straight.flow().phases[0].velocity[1].values());
  const auto& a = straight.simulation().particles();
  const auto& b = resumed->simulation().particles();
  ASSERT_EQ(a.nOwned, b.nOwned);
  for (std::size_t i = 0; i < a.nOwned; ++i) {
    EXPECT_EQ(a.id[i], b.id[i]);
    EXPECT_EQ(a.x[i], b.x[i]) << i;
    EXPECT_EQ(a.v[i], b.v[i]) << i;
  }
  // The particles moved: the comparison above could fail.
  const auto fresh = smallBedParticles();
  double moved = 0.0;
  for (std::size_t i = 0; i < a.nOwned; ++i) moved = std::max(moved, (a.x[i] - fresh.x[i]).norm());
  EXPECT_GT(moved, 0.0);
  // Frames of both kinds open: particles with the drag as external force, the gas's fields.
  straight.writeFrames();
  EXPECT_TRUE(std::filesystem::exists(scratch.dir / "a" / "particles.xmf"));
  EXPECT_TRUE(std::filesystem::exists(scratch.dir / "a" / "gas" / "fields.xmf"));
  EXPECT_EQ(straight.particleFrame().externalForce.size(), a.nOwned);
}

// With cell_average the drag is recorded only for an observed step's frame: such a frame carries
// each particle's drag (not zero: the gas moves them), and a frame after an unobserved step none,
// rather than a record left over from an earlier step.
TEST(TfdemEngine, AFrameCarriesTheDragOfItsOwnStep) {
  Scratch scratch("grainbridge-tfdem-frame-drag");
  const TfdemSetup setup = smallBed(DragTransfer::CellAverage, GasReaction::CellAverage, VolumeDeposition::CentreCell);
  const fluid::StaggeredGrid grid(setup.grid);
  TfdemEngine e(setup, smallBedParticles(), uniformGas(grid, 1.0), scratch.dir, core::io::ArtifactStamp{"test"});
  e.advance(true);
  const auto& observed = e.particleFrame().externalForce;
  ASSERT_EQ(observed.size(), e.simulation().particles().nOwned);
  double largest = 0.0;
  for (const Vec3& f : observed) largest = std::max(largest, f.norm());
  EXPECT_GT(largest, 0.0);
  e.advance(false);
  EXPECT_TRUE(e.particleFrame().externalForce.empty());
  e.advance(true);
  EXPECT_EQ(e.particleFrame().externalForce.size(), e.simulation().particles().nOwned);
}

TEST(TfdemEngine, WithTheGasOffTheBedSettlesAndTheGasWaits) {
  Scratch scratch("grainbridge-tfdem-settle");
  const TfdemSetup setup = smallBed(DragTransfer::CellAverage, GasReaction::CellAverage, VolumeDeposition::CentreCell);
  const fluid::StaggeredGrid grid(setup.grid);
  TfdemEngine e(setup, smallBedParticles(), uniformGas(grid, 1.0), scratch.dir, core::io::ArtifactStamp{"test"});
  const fluid::FlowState before = e.flow();
  const auto start = smallBedParticles();
  e.setGasActive(false);
  for (int step = 0; step < 20; ++step) e.advance(false);
  EXPECT_EQ(e.flow().pressure.values(), before.pressure.values());
  EXPECT_EQ(e.flow().phases[0].velocity[1].values(), before.phases[0].velocity[1].values());
  EXPECT_NEAR(e.time(), e.simulation().time(), 1e-14);  // two sums of the same steps
  EXPECT_NEAR(e.time(), 20 * setup.fluidDt(), 1e-15);
  // The particles fell under gravity alone, and the gas's fractions follow them.
  const auto& p = e.simulation().particles();
  double drop = 0.0;  // sums: the order of the particles may have changed at a re-sort
  for (std::size_t i = 0; i < p.nOwned; ++i) drop += (start.x[i] - p.x[i]).y();
  EXPECT_GT(drop, 0.0);
  const ParticleDeposit now = depositParticles(grid, p, VolumeDeposition::CentreCell);
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (grid.interior(c)) {
      EXPECT_EQ(now.fraction[c], e.flow().phases[1].fraction[c]) << c;
    }
  }
  e.restartClock();
  EXPECT_EQ(e.time(), 0.0);
  EXPECT_EQ(e.simulation().time(), 0.0);
  EXPECT_EQ(e.step(), 0);
  e.setGasActive(true);
  e.advance(false);
  EXPECT_NE(e.flow().pressure.values(), before.pressure.values());
}
