// The two drag transfers agree where they must: with every particle of a cell moving at the cell's
// mean velocity (and so the cell's slip), Eq. 7.29's per-particle drag B_p (u_p - v_p) is Eq.
// 7.33's share V_p beta (v_g - v_s) / eps_s, and the drag summed over a cell's particles (what
// the summed gas reaction hands the gas, Eq. 7.32) is the cell-average exchange beta (v_g - v_s) V
// (Eq. 7.33): to round-off.
#include "engines/tfdem/ParticleForces.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engines/fluid/StaggeredGrid.hpp"
#include "tests/engines/tfdem/TfdemTestSupport.hpp"

using namespace grainbridge;
using namespace grainbridge::tfdem;
using namespace grainbridge::tfdem::testing;

namespace {

TEST(ParticleForces, PerParticleDragOfParticlesAtTheirCellsVelocityIsTheCellAverage) {
  const fluid::StaggeredGrid grid(boxGrid({3, 6, 3}, 5e-3));
  dem::Particles p = randomBeads(300, 1e-3, 2500.0, Vec3::Constant(5e-4), Vec3(0.0145, 0.029, 0.0145), 5);
  // Each particle at a velocity of its cell's own: then the cell's mean velocity is that velocity.
  ParticleDeposit deposit = depositParticles(grid, p, VolumeDeposition::CentreCell);
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    ASSERT_EQ(deposit.offset[i + 1] - deposit.offset[i], 1u);
    const auto cell = grid.coordinates(deposit.shares[deposit.offset[i]].cell);
    p.v[i] = Vec3(0.01 * cell[0] - 0.02, 0.05 * cell[1] - 0.1, 0.02 * cell[2]);
  }
  deposit = depositParticles(grid, p, VolumeDeposition::CentreCell);
  fluid::FlowState state = uniformGas(grid, 0.9);
  setParticlePhase(deposit, state.phases[1]);
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (!grid.interior(c)) continue;
    state.phases[0].fraction[c] = 1.0 - deposit.fraction[c];
    state.phases[0].velocity[0][c] = 0.1 * std::sin(static_cast<double>(c));  // a slip with a cross part
  }
  const Gas gas{1.2, 1.8e-5};
  const auto law = closures::GasSolidsDrag::byName("ergun_wen_yu");
  const ParticleGasModel model(gas, law, GasReaction::CellAverage, deposit, nullptr);
  std::vector<double> beta(grid.paddedCount(), 0.0);
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (grid.interior(c)) beta[c] = model.cellBeta(state, c);
  }
  const std::vector<Vec3> cellDrag = cellDragPerSolidsVolume(state, deposit, beta);

  ParticleForceSettings settings;
  settings.gas = gas;
  settings.transfer = DragTransfer::CellAverage;
  dem::Particles averaged = p;
  setParticleForces(averaged, state, deposit, cellDrag, law, settings);
  settings.transfer = DragTransfer::PerParticle;
  dem::Particles own = p;
  setParticleForces(own, state, deposit, cellDrag, law, settings);

  std::vector<Vec3> summed(grid.paddedCount(), Vec3::Zero());
  double scale = 0.0;
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    const Vec3 fAverage = averaged.couplingA[i];
    const Vec3 fOwn = own.couplingB[i] * (own.couplingU[i] - p.v[i]);
    scale = std::max(scale, fAverage.norm());
    EXPECT_LE((fOwn - fAverage).norm(), 1e-12 * fAverage.norm() + 1e-300) << "particle " << i;
    summed[deposit.shares[deposit.offset[i]].cell] += fOwn;
  }
  ASSERT_GT(scale, 0.0);
  // The summed reaction per cell against the cell-average exchange beta (v_g - v_s) V.
  const double V = grid.cellVolume();
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (!grid.interior(c) || !(deposit.fraction[c] > 0.0)) continue;
    const Vec3 exchange = cellDrag[c] * deposit.fraction[c] * V;
    EXPECT_LE((summed[c] - exchange).norm(), 1e-12 * exchange.norm() + 1e-12 * scale) << "cell " << c;
  }
}

}  // namespace
