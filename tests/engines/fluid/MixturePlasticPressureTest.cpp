// With several solids phases, a phase's momentum sees its volume share of the mixture's plastic
// pressure gradient, (eps_sm / eps_s) grad(eps_s P*), not the gradient of its own eps_sm P*
// (Eq. 3.26; MFiX's EP_s(M)/SUM_EPS_CP, Momentum.cpp): two cells of a packed
// mixture, a thin phase whose fraction falls by two decades from one cell to the next, and the
// force on the face between them is the thin phase's share of the mixture's gradient. One solids
// phase keeps the gradient of its own pressure.
#include <gtest/gtest.h>

#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/Momentum.hpp"

using namespace grainbridge;
using namespace grainbridge::fluid;

namespace {

StaggeredGrid twoCells() {
  core::data::GridGeometry g;
  g.cells = {2, 1, 1};
  g.spacing = Vec3(0.01, 0.01, 0.01);
  return StaggeredGrid(g);
}

// The x-momentum b of every solids phase on the face between the two cells, at rest, without
// gravity or gas pressure gradient: only the solids-pressure force is left.
std::vector<double> faceForces(const std::vector<std::array<double, 2>>& fractions,
                               const std::vector<std::array<double, 2>>& plastic) {
  const StaggeredGrid grid = twoCells();
  const std::size_t M = fractions.size() + 1;
  const Boundaries boundaries(grid, {}, M);
  FlowState state(grid, M);
  FlowProperties props;
  for (std::size_t m = 0; m < M; ++m) props.phases.emplace_back(grid);
  const std::array<std::size_t, 2> cells{grid.index(0, 0, 0), grid.index(1, 0, 0)};
  for (std::size_t m = 1; m < M; ++m) {
    for (std::size_t k = 0; k < 2; ++k) {
      state.phases[m].fraction[cells[k]] = fractions[m - 1][k];
      props.phases[m].density[cells[k]] = 2500.0;
      props.phases[m].plasticPressure[cells[k]] = plastic[m - 1][k];
      props.phases[m].solidsPressure[cells[k]] = plastic[m - 1][k];  // no kinetic part
    }
  }
  MomentumInputs in;
  in.state = &state;
  in.old = &state;
  in.properties = &props;
  in.oldProperties = &props;
  in.boundaries = &boundaries;
  in.dt = 0.0;
  in.diluteFraction = 1e-6;
  std::vector<double> forces;
  for (std::size_t m = 1; m < M; ++m) {
    std::array<FaceField, 3> flux{FaceField(grid, 0), FaceField(grid, 1), FaceField(grid, 2)};
    forces.push_back(assembleMomentum(in, m, 0, flux).b(cells[0]));
  }
  return forces;
}

}  // namespace

TEST(MixturePlasticPressure, EachPhaseFeelsItsShareOfTheMixtureGradient) {
  const double pStar = 2.0e4, A = 1e-4;  // P* in both cells [Pa], face area [m^2]
  const std::array<double, 2> bulk{0.58, 0.57}, thin{1e-3, 1e-5};
  const auto forces = faceForces({bulk, thin}, {{{bulk[0] * pStar, bulk[1] * pStar}}, {{thin[0] * pStar, thin[1] * pStar}}});
  const double mixtureGradient = (bulk[1] + thin[1] - bulk[0] - thin[0]) * pStar;
  const double shareThin = 0.5 * (thin[0] + thin[1]) / (0.5 * (bulk[0] + bulk[1] + thin[0] + thin[1]));
  EXPECT_NEAR(forces[1], -shareThin * mixtureGradient * A, 1e-12);
  EXPECT_NEAR(forces[0], -(1.0 - shareThin) * mixtureGradient * A, 1e-12);
  // The own-gradient form would push the thin phase with P* times its own fraction's drop:
  // 100 times its share here, towards the cell it has left.
  const double ownGradient = (thin[1] - thin[0]) * pStar;
  EXPECT_GT(std::abs(ownGradient), 50.0 * std::abs(shareThin * mixtureGradient));
  EXPECT_NEAR(forces[0] + forces[1], -mixtureGradient * A, 1e-12);  // the mixture's force is kept
}

TEST(MixturePlasticPressure, OneSolidsPhaseKeepsTheGradientOfItsOwnPressure) {
  const double pStar = 2.0e4, A = 1e-4;
  const auto forces = faceForces({{0.58, 0.50}}, {{{0.58 * pStar, 0.50 * pStar}}});
  EXPECT_DOUBLE_EQ(forces[0], -(0.50 - 0.58) * pStar * A);
}
