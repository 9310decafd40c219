// A phase the caller gives (TF-DEM's particles on the grid, FlowModel::givenPhase): the step leaves
// its fraction and velocity as given, the gas feels its drag at its given velocity, the gas
// continuity sees its fraction change over the step, and a model's explicit momentum source
// enters the momentum balance. Each check is against the balance the steady column must satisfy.
#include <gtest/gtest.h>

#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/MassFlux.hpp"
#include "engines/fluid/SimpleStep.hpp"

using namespace grainbridge;
using namespace grainbridge::fluid;

namespace {

constexpr double kGasDensity = 1.2;

// Incompressible air and one given solids phase with a constant drag coefficient where it is, and
// an optional upward momentum source on the gas.
struct GivenSolidsModel final : FlowModel {
  double beta = 0.0;      // F_gs [kg/(m^3 s)] where eps_s > 0
  double gasSource = 0.0;  // along y [N/m^3]
  void evaluate(const FlowState& state, FlowProperties& p) const override {
    if (gasSource != 0.0) p.phases[0].momentumSource.assign(3, CellField(state.grid(), 0.0));
    for (std::size_t c = 0; c < state.grid().paddedCount(); ++c) {
      p.phases[0].density[c] = kGasDensity;
      p.phases[0].shearViscosity[c] = 1.8e-5 * state.phases[0].fraction[c];
      p.phases[1].density[c] = 2500.0;
      p.dragCoefficient[1][c] = state.phases[1].fraction[c] > 0.0 ? beta : 0.0;
      if (gasSource != 0.0) p.phases[0].momentumSource[1][c] = gasSource;
    }
  }
  [[nodiscard]] bool givenPhase(std::size_t m) const override { return m == 1; }
};

// A vertical column of one cell's width: gas in at the bottom, out at the top, free-slip sides so
// the flow stays one-dimensional.
struct Column {
  static constexpr int kCells = 20;
  static constexpr double kCell = 0.01;
  double solids;  // the given fraction, everywhere
  double inflow;  // the gas's interstitial inflow speed [m/s]
  StaggeredGrid grid;
  Boundaries boundaries;
  FlowState state;
  Column(double eps_s, double u)
      : solids(eps_s), inflow(u), grid(geometry()), boundaries(grid, patches(eps_s, u), 2), state(grid, 2) {
    for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
      state.phases[1].fraction[c] = solids;
      state.phases[0].fraction[c] = 1.0 - solids;
      state.phases[0].velocity[1][c] = inflow;
      state.pressure[c] = 101325.0;
    }
  }
  static core::data::GridGeometry geometry() {
    core::data::GridGeometry g;
    g.cells = {1, kCells, 1};
    g.spacing = Vec3(kCell, kCell, kCell);
    return g;
  }
  static std::vector<BoundaryPatch> patches(double eps_s, double u) {
    BoundaryPatch inlet;
    inlet.kind = BoundaryKind::VelocityInlet;
    inlet.side = YLow;
    inlet.phases = {PhaseInflow{1.0 - eps_s, Vec3(0.0, u, 0.0)}, PhaseInflow{eps_s, Vec3::Zero()}};
    BoundaryPatch outlet;
    outlet.kind = BoundaryKind::PressureOutlet;
    outlet.side = YHigh;
    outlet.pressure = 101325.0;
    outlet.phases = {PhaseInflow{1.0, Vec3::Zero()}, PhaseInflow{0.0, Vec3::Zero()}};
    BoundaryPatch left, right;
    left.kind = right.kind = BoundaryKind::FreeSlipWall;
    left.side = XLow;
    right.side = XHigh;
    return {inlet, outlet, left, right};
  }
  [[nodiscard]] double pressureAt(int j) const { return state.pressure[grid.index(0, j, 0)]; }
};

SimpleSettings tight(Vec3 gravity) {
  SimpleSettings s;
  s.gravity = gravity;
  s.tolerance = 1e-12;
  s.maxIterations = 200;
  return s;
}

// Steps the column until its pressure field stops changing.
void runToSteady(Column& column, const FlowModel& model, const SimpleSettings& settings) {
  for (int step = 0; step < 200; ++step) {
    const CellField before = column.state.pressure;
    const StepResult r = advance(column.state, 1e-2, model, column.boundaries, settings);
    ASSERT_TRUE(r.converged) << r.equation << " " << r.residual << " " << r.failure;
    double change = 0.0;
    for (int j = 0; j < Column::kCells; ++j) {
      const std::size_t c = column.grid.index(0, j, 0);
      change = std::max(change, std::abs(column.state.pressure[c] - before[c]));
    }
    if (change < 1e-11) return;
  }
  FAIL() << "the column did not reach a steady state";
}

}  // namespace

TEST(GivenPhase, TheStepLeavesItsFractionAndVelocityAsGiven) {
  Column column(0.4, 0.5);
  GivenSolidsModel model;
  model.beta = 2e4;
  for (std::size_t c = 0; c < column.grid.paddedCount(); ++c) column.state.phases[1].velocity[1][c] = 0.01;
  column.boundaries.apply(column.state);
  const FlowState given = column.state;
  ASSERT_TRUE(advance(column.state, 1e-3, model, column.boundaries, tight(Vec3(0, -9.81, 0))).converged);
  // Inside the domain; the ghosts are the boundary conditions', which the step writes.
  for (int j = 0; j < Column::kCells; ++j) {
    const std::size_t c = column.grid.index(0, j, 0);
    EXPECT_EQ(column.state.phases[1].fraction[c], given.phases[1].fraction[c]) << j;
    EXPECT_EQ(column.state.phases[1].velocity[1][c], given.phases[1].velocity[1][c]) << j;
  }
  // The gas did move: the check above could fail for a phase that is solved.
  EXPECT_NE(column.state.pressure.values(), given.pressure.values());
}

// Steady 1D gas momentum through a fixed bed: eps_g dP/dy = -F_gs (v_g - v_s) - eps_g rho_g g, with
// v_g = U / eps_g and v_s = 0, between every pair of neighbouring cells.
TEST(GivenPhase, TheGasFeelsTheDragOfTheGivenPhaseAtItsGivenVelocity) {
  const double eps_s = 0.4, eps_g = 0.6, u = 0.5, beta = 2e4, g = 9.81;
  Column column(eps_s, u);
  GivenSolidsModel model;
  model.beta = beta;
  runToSteady(column, model, tight(Vec3(0, -g, 0)));
  const double expected = -(beta * u / eps_g + kGasDensity * g) * Column::kCell;  // P_{j+1} - P_j
  for (int j = 0; j + 1 < Column::kCells; ++j)
    EXPECT_NEAR(column.pressureAt(j + 1) - column.pressureAt(j), expected, 1e-9 * std::abs(expected)) << j;
}

TEST(GivenPhase, AnExplicitMomentumSourceBalancesThePressureGradient) {
  const double source = 150.0;  // N/m^3 upward on the gas
  Column column(0.0, 0.3);
  GivenSolidsModel model;
  model.gasSource = source;
  runToSteady(column, model, tight(Vec3::Zero()));
  for (int j = 0; j + 1 < Column::kCells; ++j)
    EXPECT_NEAR(column.pressureAt(j + 1) - column.pressureAt(j), source * Column::kCell, 1e-9 * source * Column::kCell)
        << j;
}

// The particles pack into one cell over a step: the gas they displace, V d eps_s, leaves through
// the outlet on top of what comes in (incompressible gas, the old level's fractions given apart).
TEST(GivenPhase, TheGasContinuitySeesTheGivenFractionChangeOverTheStep) {
  const double eps_s = 0.4, u = 0.5, dt = 1e-3, added = 0.05;
  Column column(eps_s, u);
  GivenSolidsModel model;
  model.beta = 1e3;
  const SimpleSettings settings = tight(Vec3::Zero());
  runToSteady(column, model, settings);
  const FlowState old = column.state;
  column.state.phases[1].fraction[column.grid.index(0, 7, 0)] += added;
  const StepResult r = advance(column.state, old, dt, model, column.boundaries, settings);
  ASSERT_TRUE(r.converged) << r.equation << " " << r.residual << " " << r.failure;
  EXPECT_DOUBLE_EQ(column.state.time, old.time + dt);
  EXPECT_DOUBLE_EQ(column.state.phases[0].fraction[column.grid.index(0, 7, 0)], 1.0 - eps_s - added);
  const double area = Column::kCell * Column::kCell, volume = area * Column::kCell;
  const auto gasVolumeFluxOnFace = [&](int j) {  // the high face of cell j
    const std::size_t f = column.grid.index(0, j, 0);
    const double eps = j + 1 < Column::kCells ? column.state.phases[0].fraction[f] : 1.0 - eps_s;
    return eps * column.state.phases[0].velocity[1][f] * area;
  };
  const double in = (1.0 - eps_s) * u * area;
  EXPECT_NEAR(gasVolumeFluxOnFace(Column::kCells - 1), in + added * volume / dt, 1e-9 * in);
  // Below the packing cell the gas flows as before; above it carries the displaced volume.
  EXPECT_NEAR(gasVolumeFluxOnFace(3), in, 1e-9 * in);
  EXPECT_NEAR(gasVolumeFluxOnFace(12), in + added * volume / dt, 1e-9 * in);
}
