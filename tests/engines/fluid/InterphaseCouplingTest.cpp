// The point-coupled partial elimination of InterphaseCoupling: on a face without neighbours
// (a_nb = 0, so every phase's equation is a_m u_m = a_m u_m^0 plus the exchanges) one pass of
// the eliminated equations must give the exact solution of the coupled system, whatever the
// number of phases and exchanges:
//   - two solids phases exchanging momentum by a fixed F_sml, no gas drag: the relative velocity
//     decays as implicit Euler says, 1 / (1 + F dV (1/a_l + 1/a_m)), and their momentum is kept;
//   - the gas and two solids phases, every pair coupled: the solution of K u = a u^0.
#include "engines/fluid/InterphaseCoupling.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

namespace grainbridge::fluid {
namespace {

StaggeredGrid oneCell() {
  core::data::GridGeometry g;
  g.origin = Vec3::Zero();
  g.spacing = Vec3(0.01, 0.01, 0.01);
  g.cells = {1, 1, 1};
  return StaggeredGrid(g);
}

struct Face {
  explicit Face(const StaggeredGrid& grid, std::vector<double> fractions, std::vector<double> densities,
                std::vector<double> velocities, double dt)
      : state(grid, fractions.size()), a(fractions.size()) {
    f = grid.index(0, 0, 0);
    for (std::size_t m = 0; m < fractions.size(); ++m) {
      for (double& e : state.phases[m].fraction.values()) e = fractions[m];
      state.phases[m].velocity[0][f] = velocities[m];
      properties.phases.emplace_back(grid);
      properties.dragCoefficient.emplace_back(grid);
      a[m] = fractions[m] * densities[m] * grid.cellVolume() / dt;
      systems.emplace_back(grid);
      systems[m].ap(f) = a[m];
      systems[m].b(f) = a[m] * velocities[m];
    }
  }
  // u_m after the elimination: its equation has no neighbours left.
  [[nodiscard]] double solved(std::size_t m) const { return systems[m].b(f) / systems[m].ap(f); }

  FlowState state;
  FlowProperties properties;
  std::vector<StencilSystem> systems;
  std::vector<double> a;
  std::size_t f = 0;
};

TEST(InterphaseCoupling, TwoSolidsPhasesRelaxTheirSlipAsImplicitEulerAndKeepTheirMomentum) {
  const StaggeredGrid grid = oneCell();
  const double dt = 1e-3, F = 4.0e4;
  Face face(grid, {0.5, 0.3, 0.2}, {1.2, 2500.0, 2520.0}, {0.0, 0.4, -0.1}, dt);
  face.properties.solidsDrag.emplace_back(grid, 1, 2);
  for (double& x : face.properties.solidsDrag[0].coefficient.values()) x = F;
  (void)coupleAndRelax(face.systems, face.state, face.properties, 0, 1.0, 1e-4);
  const double V = grid.cellVolume();
  const double decay = 1.0 / (1.0 + F * V * (1.0 / face.a[1] + 1.0 / face.a[2]));
  EXPECT_NEAR(face.solved(1) - face.solved(2), decay * 0.5, 1e-12);
  const double before = face.a[1] * 0.4 + face.a[2] * -0.1;
  EXPECT_NEAR(face.a[1] * face.solved(1) + face.a[2] * face.solved(2), before, 1e-12 * std::abs(before) + 1e-15);
  EXPECT_DOUBLE_EQ(face.solved(0), 0.0);  // no gas drag: the gas is untouched
}

TEST(InterphaseCoupling, EveryExchangeImplicitGivesTheCoupledSolution) {
  const StaggeredGrid grid = oneCell();
  const double dt = 2e-4, V = grid.cellVolume();
  const std::vector<double> u0 = {1.3, 0.2, -0.4};
  Face face(grid, {0.45, 0.35, 0.2}, {1.2, 2500.0, 2520.0}, u0, dt);
  const double beta1 = 3.0e3, beta2 = 1.5e3, F = 2.0e4;
  for (double& x : face.properties.dragCoefficient[1].values()) x = beta1;
  for (double& x : face.properties.dragCoefficient[2].values()) x = beta2;
  face.properties.solidsDrag.emplace_back(grid, 1, 2);
  for (double& x : face.properties.solidsDrag[0].coefficient.values()) x = F;
  const auto corrections = coupleAndRelax(face.systems, face.state, face.properties, 0, 1.0, 1e-4);
  Eigen::Matrix3d K;
  K << face.a[0] + (beta1 + beta2) * V, -beta1 * V, -beta2 * V,  //
      -beta1 * V, face.a[1] + (beta1 + F) * V, -F * V,          //
      -beta2 * V, -F * V, face.a[2] + (beta2 + F) * V;
  const Eigen::Vector3d exact = K.lu().solve(Eigen::Vector3d(face.a[0] * u0[0], face.a[1] * u0[1], face.a[2] * u0[2]));
  for (std::size_t m = 0; m < 3; ++m) EXPECT_NEAR(face.solved(m), exact[static_cast<Eigen::Index>(m)], 1e-12) << m;
  // The gas-pressure correction coefficients are the same matrix's answer to eps_m A.
  const Eigen::Vector3d d = K.lu().solve(Eigen::Vector3d(0.45, 0.35, 0.2) * grid.faceArea(0));
  for (std::size_t m = 0; m < 3; ++m)
    EXPECT_NEAR(corrections.pressure[m][face.f], d[static_cast<Eigen::Index>(m)], 1e-12 * std::abs(d[0])) << m;
}

TEST(InterphaseCoupling, OneSolidsPhaseClosedFormIsTheCoupledSolution) {
  const StaggeredGrid grid = oneCell();
  const double dt = 5e-4, V = grid.cellVolume(), beta = 8.0e3;
  const std::vector<double> u0 = {2.0, -0.3};
  Face face(grid, {0.55, 0.45}, {1.2, 2526.0}, u0, dt);
  for (double& x : face.properties.dragCoefficient[1].values()) x = beta;
  (void)coupleAndRelax(face.systems, face.state, face.properties, 0, 1.0, 1e-4);
  Eigen::Matrix2d K;
  K << face.a[0] + beta * V, -beta * V, -beta * V, face.a[1] + beta * V;
  const Eigen::Vector2d exact = K.lu().solve(Eigen::Vector2d(face.a[0] * u0[0], face.a[1] * u0[1]));
  EXPECT_NEAR(face.solved(0), exact[0], 1e-12);
  EXPECT_NEAR(face.solved(1), exact[1], 1e-12);
}

}  // namespace
}  // namespace grainbridge::fluid
