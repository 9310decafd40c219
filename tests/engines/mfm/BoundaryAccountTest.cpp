// The boundary mass account (engines/fluid/BoundaryFlow, issue 29): what a velocity inlet feeds is
// rho eps U A per second of each phase, the solids a column gains is exactly what crossed its
// boundary (the closing continuity solve moves mass with the fluxes the account sums), the gas's
// to the continuity tolerance, and the account survives a checkpoint bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engines/mfm/MfmEngine.hpp"
#include "tests/engines/mfm/GrainBed.hpp"
#include "tests/support/TempDir.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;

namespace {

constexpr double kGasInflow = 0.3, kSolidsInflow = 0.1, kFeedFraction = 0.05;

// An empty 2 x 16 column of the grain bed's cells fed through its bottom with gas and grains;
// the gas leaves through the top outlet, the grains do not reach it in the time run.
GrainBed fedColumn() {
  GrainBedSpec spec;
  spec.bedCells = 0;
  spec.inflow = kGasInflow;
  GrainBed column = grainBed(spec);
  for (auto& patch : column.setup.patches) {
    if (patch.kind != fluid::BoundaryKind::VelocityInlet) continue;
    patch.phases = {fluid::PhaseInflow{1.0 - kFeedFraction, Vec3(0.0, kGasInflow, 0.0)},
                    fluid::PhaseInflow{kFeedFraction, Vec3(0.0, kSolidsInflow, 0.0)}};
  }
  column.setup.interval = 0.01;
  return column;
}

std::size_t inletIndex(const mfm::MultiFluidSetup& setup) {
  for (std::size_t k = 0; k < setup.patches.size(); ++k)
    if (setup.patches[k].kind == fluid::BoundaryKind::VelocityInlet) return k;
  return 0;
}

}  // namespace

TEST(BoundaryAccount, AFedColumnGainsWhatItsInletCarriesOfEachPhase) {
  TempDir dir;
  const GrainBed column = fedColumn();
  mfm::MfmEngine run(column.setup, [&](mfm::MultiFluidEngine& e) { mfm::initialise(e, column.initial); },
                     dir.path(), core::io::ArtifactStamp{"test"});
  // The gas's error, held - held0 - in + out, after the first interval and at the end.
  const auto gasError = [&run] {
    const auto& st = run.engine().statistics();
    const auto crossed = fluid::total(st.boundaryMass[0]);
    return run.engine().heldMass()[0] - st.initialMass[0] - crossed.in + crossed.out;
  };
  run.advance(false);
  const double startError = gasError();
  for (int s = 1; s < 10; ++s) run.advance(false);  // 0.1 s

  const auto& engine = run.engine();
  const auto& stats = engine.statistics();
  const double t = engine.time();
  ASSERT_NEAR(t, 0.1, 1e-12);
  const auto& g = column.setup.geometry;
  const double area = g.cells[0] * g.spacing.x() * g.spacing.z();
  const std::size_t inlet = inletIndex(column.setup);
  const auto held = engine.heldMass();
  ASSERT_EQ(stats.boundaryMass.size(), 2u);
  ASSERT_EQ(stats.initialMass.size(), 2u);

  // The inlet: rho eps U A t, gas and grains.
  const double gasFed = kAirDensity * (1.0 - kFeedFraction) * kGasInflow * area * t;
  const double solidsFed = kGrainDensity * kFeedFraction * kSolidsInflow * area * t;
  EXPECT_NEAR(stats.boundaryMass[0][inlet].in, gasFed, 1e-9 * gasFed);
  EXPECT_NEAR(stats.boundaryMass[1][inlet].in, solidsFed, 1e-9 * solidsFed);
  EXPECT_EQ(stats.boundaryMass[0][inlet].out, 0.0);

  // The grains: all of it held (the column started empty), none left through the top.
  const auto [solidsIn, solidsOut] = fluid::total(stats.boundaryMass[1]);
  const auto [gasIn, gasOut] = fluid::total(stats.boundaryMass[0]);
  EXPECT_EQ(stats.initialMass[1], 0.0);
  EXPECT_EQ(solidsOut, 0.0);
  EXPECT_NEAR(held[1] - stats.initialMass[1], solidsIn - solidsOut, 1e-9 * solidsIn);
  // The gas: out through the top what the grains do not displace. A step meets the gas
  // continuity to the tolerance only: the first steps, which start the feed, leave their residual
  // (at most the tolerance times the gas held), and every step after them balances to round-off.
  const double endError = gasError();
  std::printf("gas: error %.3e kg after the first 10 ms, %.3e kg at 0.1 s (inflow %.3e kg, held %.3e kg)\n",
              startError, endError, gasIn, held[0]);
  EXPECT_LT(std::abs(startError), column.setup.settings.tolerance * stats.initialMass[0]);
  EXPECT_LT(std::abs(endError - startError), 1e-12 * gasIn);
  EXPECT_GT(gasOut, 0.9 * gasIn);
}

TEST(BoundaryAccount, SurvivesACheckpointBitForBit) {
  TempDir dir;
  const GrainBed column = fedColumn();
  const auto initial = [&](mfm::MultiFluidEngine& e) { mfm::initialise(e, column.initial); };
  const core::io::ArtifactStamp stamp{"test"};
  mfm::MfmEngine straight(column.setup, initial, dir.path() / "a", stamp);
  for (int s = 0; s < 6; ++s) straight.advance(false);
  mfm::MfmEngine first(column.setup, initial, dir.path() / "b", stamp);
  for (int s = 0; s < 3; ++s) first.advance(false);
  first.saveState(dir.path() / "state.h5", "key");
  auto resumed = mfm::MfmEngine::restore(column.setup, dir.path() / "state.h5", "key", dir.path() / "c", stamp);
  for (int s = 0; s < 3; ++s) resumed->advance(false);

  const auto& a = straight.engine().statistics();
  const auto& b = resumed->engine().statistics();
  EXPECT_EQ(a.initialMass, b.initialMass);
  ASSERT_EQ(a.boundaryMass.size(), b.boundaryMass.size());
  for (std::size_t m = 0; m < a.boundaryMass.size(); ++m) {
    ASSERT_EQ(a.boundaryMass[m].size(), b.boundaryMass[m].size());
    for (std::size_t p = 0; p < a.boundaryMass[m].size(); ++p) {
      EXPECT_EQ(a.boundaryMass[m][p].in, b.boundaryMass[m][p].in) << "phase " << m << " patch " << p;
      EXPECT_EQ(a.boundaryMass[m][p].out, b.boundaryMass[m][p].out) << "phase " << m << " patch " << p;
    }
  }
  EXPECT_GT(a.boundaryMass[1][inletIndex(column.setup)].in, 0.0);
}
