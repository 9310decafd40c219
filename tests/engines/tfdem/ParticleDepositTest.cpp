// The particles on the gas grid (Eqs. 7.35-7.36): whatever the deposition, the cells hold the
// particles' whole volume and momentum (sum eps_s V_cell = sum V_p), and the solids phase the gas
// is given carries them.
#include <gtest/gtest.h>

#include "engines/tfdem/ParticleDeposit.hpp"
#include "tests/engines/tfdem/TfdemTestSupport.hpp"

using namespace grainbridge;
using namespace grainbridge::tfdem;
using namespace grainbridge::tfdem::testing;

namespace {

void expectConserved(VolumeDeposition deposition, int nz) {
  const auto g = boxGrid({4, 5, nz}, 5e-3);
  const fluid::StaggeredGrid grid(g);
  const double d = nz == 1 ? 3e-3 : 1.5e-3;  // 2D: one layer at mid-depth
  const Vec3 lo = Vec3::Constant(0.5 * d), hi = extent(g) - Vec3::Constant(0.5 * d);
  dem::Particles p;
  if (nz == 1) {
    // One layer at mid-depth, off the cell centres so that spheres straddle cell faces.
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 4; ++j) {
        const Vec3 x(4e-3 + 6e-3 * i, 4e-3 + 5.5e-3 * j + 4e-4 * i, 0.5 * g.spacing.z());
        p.addOwned(3 * j + i, 0, 0.5 * d, 1e-5, x, Vec3::Zero(), Vec3::Zero(), false);
      }
    }
  } else {
    p = randomBeads(150, d, 2500.0, lo, hi, 7);
  }
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double volume = 0.0;
  Vec3 momentum = Vec3::Zero();
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    p.v[i] = Vec3(u(rng), u(rng), nz == 1 ? 0.0 : u(rng));
    volume += particleVolume(p.radius[i]);
    momentum += particleVolume(p.radius[i]) * p.v[i];
  }
  const ParticleDeposit dep = depositParticles(grid, p, deposition);
  double held = 0.0;
  Vec3 carried = Vec3::Zero();
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (!grid.interior(c)) {
      EXPECT_EQ(dep.fraction[c], 0.0);
      continue;
    }
    held += dep.fraction[c] * grid.cellVolume();
    carried += dep.fraction[c] * grid.cellVolume() * dep.velocity[c];
    if (dep.fraction[c] > 0.0) {
      EXPECT_NEAR(dep.diameter[c], d, 1e-15);
    }
  }
  EXPECT_NEAR(held, volume, 1e-12 * volume);
  EXPECT_LE((carried - momentum).norm(), 1e-12 * volume);
  // The shares of every particle sum to one (all inside the grid).
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    double sum = 0.0;
    for (std::size_t k = dep.offset[i]; k < dep.offset[i + 1]; ++k) sum += dep.shares[k].fraction;
    EXPECT_NEAR(sum, 1.0, 1e-12) << i;
  }
}

}  // namespace

TEST(ParticleDeposit, CentreCellHoldsEveryParticleVolumeIn3D) { expectConserved(VolumeDeposition::CentreCell, 3); }
TEST(ParticleDeposit, ExactOverlapHoldsEveryParticleVolumeIn3D) { expectConserved(VolumeDeposition::ExactOverlap, 3); }
TEST(ParticleDeposit, CentreCellHoldsEveryParticleVolumeIn2D) { expectConserved(VolumeDeposition::CentreCell, 1); }
TEST(ParticleDeposit, ExactOverlapHoldsEveryParticleVolumeIn2D) { expectConserved(VolumeDeposition::ExactOverlap, 1); }

TEST(ParticleDeposit, TheGivenPhaseFaceVelocityIsTheSolidsWeightedMean) {
  const fluid::StaggeredGrid grid(boxGrid({2, 1, 1}, 1e-2));
  dem::Particles p;
  const double a = 2e-3, m = 1e-5;
  p.addOwned(0, 0, a, m, Vec3(0.005, 0.005, 0.005), Vec3(1.0, 0, 0), Vec3::Zero(), false);
  p.addOwned(1, 0, a, m, Vec3(0.015, 0.005, 0.005), Vec3(3.0, 0, 0), Vec3::Zero(), false);
  p.addOwned(2, 0, a, m, Vec3(0.016, 0.004, 0.004), Vec3(3.0, 0, 0), Vec3::Zero(), false);
  const ParticleDeposit dep = depositParticles(grid, p, VolumeDeposition::CentreCell);
  fluid::PhaseFields phase(grid);
  setParticlePhase(dep, phase);
  // Cell 1 holds twice cell 0's volume: the face between them moves at (1 + 2 * 3) / 3.
  EXPECT_NEAR(phase.velocity[0][grid.index(0, 0, 0)], 7.0 / 3.0, 1e-14);
  EXPECT_NEAR(phase.fraction[grid.index(1, 0, 0)], 2.0 * phase.fraction[grid.index(0, 0, 0)], 1e-15);
}
