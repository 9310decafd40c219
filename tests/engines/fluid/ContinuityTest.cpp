// The implicit closing of a solids phase's continuity after a converged step (Continuity.hpp):
// however fast the solids leave a thin cell, the fraction stays non-negative and the phase's
// mass is kept, where an explicit update with the same faces would have emptied the cell below
// zero.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/Continuity.hpp"
#include "engines/fluid/MassFlux.hpp"

using namespace grainbridge;
using namespace grainbridge::fluid;

TEST(Continuity, ClosingASolidsPhaseKeepsAThinCellNonNegativeAndTheMassExact) {
  core::data::GridGeometry g;
  g.cells = {8, 6, 1};
  g.spacing = Vec3(0.01, 0.01, 0.01);
  const StaggeredGrid grid(g);
  const Boundaries walls(grid, {}, 2);  // a closed box: the phase's mass cannot change
  FlowState state(grid, 2);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> fraction(0.2, 0.5), speed(-0.3, 0.3);
  PhaseFields& solids = state.phases[1];
  for (int j = 0; j < 6; ++j) {
    for (int i = 0; i < 8; ++i) {
      solids.fraction(i, j, 0) = fraction(random);
      solids.velocity[0](i, j, 0) = speed(random);
      solids.velocity[1](i, j, 0) = speed(random);
    }
  }
  // A thin cell, its solids leaving through all four faces at 1 m/s.
  solids.fraction(3, 2, 0) = 1e-6;
  solids.velocity[0](3, 2, 0) = 1.0;
  solids.velocity[0](2, 2, 0) = -1.0;
  solids.velocity[1](3, 2, 0) = 1.0;
  solids.velocity[1](3, 1, 0) = -1.0;
  walls.apply(state);
  const CellField start = solids.fraction;
  const CellField density(grid, 2500.0);
  const double dt = 1e-2;  // a Courant number of 1 on each of the thin cell's faces
  const auto flux = massFluxes(solids, density, walls, OutflowBudget{&start, dt});

  // The explicit update with these faces would leave the thin cell below zero.
  const std::size_t thin = grid.index(3, 2, 0);
  const double explicitValue =
      start[thin] - massImbalance(start, start, density, density, flux, dt, thin) * dt / (2500.0 * grid.cellVolume());
  ASSERT_LT(explicitValue, -1e-6);

  double before = 0.0;
  for (std::size_t c = 0; c < grid.paddedCount(); ++c)
    if (grid.interior(c)) before += start[c];
  static_cast<void>(solveFractionNonNegative(solids, start, density, density, flux, walls, dt));
  double after = 0.0;
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (!grid.interior(c)) continue;
    EXPECT_GE(solids.fraction[c], 0.0) << "cell " << grid.coordinates(c)[0] << "," << grid.coordinates(c)[1];
    after += solids.fraction[c];
  }
  EXPECT_NEAR(after, before, 1e-13 * before);
  EXPECT_LT(solids.fraction[thin], start[thin]);  // the thin cell still empties, just not past zero
}
