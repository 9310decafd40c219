// The gas alone in a plane channel (issue 17): uniform inflow at x = 0, a pressure outlet at
// x = L, no-slip walls at y = 0 and y = H. Downstream of the entrance the steady laminar profile
// is Poiseuille's, u(y) = 1.5 U (1 - (2y/H - 1)^2), with dP/dx = -12 mu U / H^2. The staggered
// grid with the no-slip ghost rule (Eq. 3.67) and central viscous fluxes is second order, so the
// profile's error falls by four each time the grid is halved.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/SimpleStep.hpp"

using namespace grainbridge;
using namespace grainbridge::fluid;

namespace {

constexpr double kRho = 1.2, kMu = 1.8e-5;  // air [kg/m^3], [Pa s]
constexpr double kH = 0.01, kU = 0.01;      // channel height [m], mean velocity [m/s]: Re = 6.7
constexpr double kLengths = 5.0;            // L / H

struct ConstantGas final : FlowModel {
  void evaluate(const FlowState& state, FlowProperties& p) const override {
    for (std::size_t c = 0; c < state.grid().paddedCount(); ++c) {
      const double eps = state.phases[0].fraction[c];
      p.phases[0].density[c] = kRho;
      p.phases[0].shearViscosity[c] = eps * kMu;
      p.phases[0].bulkViscosity[c] = -2.0 / 3.0 * eps * kMu;  // Stokes: no bulk viscosity
    }
  }
};

StaggeredGrid channelGrid(int ny) {
  core::data::GridGeometry g;
  g.cells = {static_cast<int>(kLengths * ny), ny, 1};
  g.spacing = Vec3(kH / ny, kH / ny, kH / ny);
  g.origin = Vec3::Zero();
  return StaggeredGrid(g);
}

std::vector<BoundaryPatch> channelPatches() {
  BoundaryPatch inlet;
  inlet.kind = BoundaryKind::VelocityInlet;
  inlet.side = XLow;
  inlet.phases = {PhaseInflow{1.0, Vec3(kU, 0.0, 0.0)}};
  BoundaryPatch outlet;
  outlet.kind = BoundaryKind::PressureOutlet;
  outlet.side = XHigh;
  outlet.pressure = 0.0;
  return {inlet, outlet};  // y sides: no-slip walls
}

struct Solved {
  double profileError;   // max |u - u_exact| / (1.5 U) across the channel at x = 4 H
  double gradientError;  // relative error of dP/dx there
};

Solved solveChannel(int ny) {
  const StaggeredGrid grid = channelGrid(ny);
  const Boundaries boundaries(grid, channelPatches(), 1);
  FlowState state(grid, 1);
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    state.phases[0].fraction[c] = 1.0;
    state.phases[0].velocity[0][c] = kU;
  }
  SimpleSettings settings;
  settings.momentumRelaxation = 0.7;
  settings.pressureRelaxation = 0.3;
  settings.tolerance = 1e-10;
  settings.maxIterations = 5000;
  const StepResult r = solveSteady(state, ConstantGas{}, boundaries, settings);
  EXPECT_TRUE(r.converged) << "after " << r.iterations << " iterations: " << r.equation << " residual " << r.residual;

  const int i = static_cast<int>(4.0 * ny);  // the face at x = (i + 1) h, a little past 4 H
  Solved out{0.0, 0.0};
  for (int j = 0; j < ny; ++j) {
    const double y = grid.cellCentre(i, j, 0).y();
    const double exact = 1.5 * kU * (1.0 - std::pow(2.0 * y / kH - 1.0, 2));
    out.profileError = std::max(out.profileError, std::abs(state.phases[0].velocity[0](i, j, 0) - exact) / (1.5 * kU));
  }
  const int mid = ny / 2;
  const double dpdx = (state.pressure(i + 1, mid, 0) - state.pressure(i, mid, 0)) / grid.spacing(0);
  const double exactGradient = -12.0 * kMu * kU / (kH * kH);
  out.gradientError = std::abs(dpdx - exactGradient) / std::abs(exactGradient);
  return out;
}

}  // namespace

TEST(ChannelFlow, DevelopedProfileIsPoiseuillesWithinOnePercent) {
  const Solved s = solveChannel(16);
  EXPECT_LT(s.profileError, 0.01);
  EXPECT_LT(s.gradientError, 0.01);
}

TEST(ChannelFlow, ProfileErrorFallsAtSecondOrder) {
  const Solved coarse = solveChannel(8), fine = solveChannel(16), finer = solveChannel(32);
  const double order1 = std::log2(coarse.profileError / fine.profileError);
  const double order2 = std::log2(fine.profileError / finer.profileError);
  std::printf("channel profile error: %.3e (8) %.3e (16) %.3e (32); orders %.2f %.2f\n", coarse.profileError,
              fine.profileError, finer.profileError, order1, order2);
  EXPECT_GT(order1, 1.8);
  EXPECT_GT(order2, 1.8);
}
