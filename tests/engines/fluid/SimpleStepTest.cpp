// What a transient step leaves when it is stopped half-way: a singular linear system met by an
// iterate is a failed step (its reason in `failure`, a smaller step is tried by the caller), any
// other error propagates, and in both cases the state is the last converged level, never the
// iterate (a kept frame or checkpoint written after it holds a solution).
#include <gtest/gtest.h>

#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/SimpleStep.hpp"
#include "engines/fluid/StencilSystem.hpp"

using namespace grainbridge;
using namespace grainbridge::fluid;

namespace {

// Air whose evaluation throws on its `failAt`-th call: the first call is the last level's, so
// failAt 3 stops the step in its second outer iteration, after the first has moved the iterate.
template <typename Thrown>
struct FailingGas final : FlowModel {
  int failAt = 3;
  mutable int calls = 0;
  void evaluate(const FlowState& state, FlowProperties& p) const override {
    if (++calls == failAt) throw Thrown("the model gave up");
    for (std::size_t c = 0; c < state.grid().paddedCount(); ++c) {
      p.phases[0].density[c] = 1.2;
      p.phases[0].shearViscosity[c] = 1.8e-5;
      p.phases[0].bulkViscosity[c] = -1.2e-5;
    }
  }
};

struct Channel {
  StaggeredGrid grid;
  Boundaries boundaries;
  FlowState state;
  Channel() : grid(geometry()), boundaries(grid, patches(), 1), state(grid, 1) {
    for (std::size_t c = 0; c < grid.paddedCount(); ++c) state.phases[0].fraction[c] = 1.0;
  }
  static core::data::GridGeometry geometry() {
    core::data::GridGeometry g;
    g.cells = {10, 4, 1};
    g.spacing = Vec3(0.01, 0.01, 0.01);
    return g;
  }
  static std::vector<BoundaryPatch> patches() {
    BoundaryPatch inlet;
    inlet.kind = BoundaryKind::VelocityInlet;
    inlet.side = XLow;
    inlet.phases = {PhaseInflow{1.0, Vec3(0.5, 0.0, 0.0)}};
    BoundaryPatch outlet;
    outlet.kind = BoundaryKind::PressureOutlet;
    outlet.side = XHigh;
    return {inlet, outlet};
  }
};

}  // namespace

TEST(SimpleStep, ASingularSystemFailsTheStepAndLeavesTheLastLevel) {
  Channel ch;
  const FlowState before = ch.state;
  const StepResult r = advance(ch.state, 1e-3, FailingGas<SingularSystem>{}, ch.boundaries, SimpleSettings{});
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.failure.find("the model gave up"), std::string::npos) << r.failure;
  EXPECT_EQ(ch.state.time, before.time);
  EXPECT_EQ(ch.state.phases[0].velocity[0].values(), before.phases[0].velocity[0].values());
  EXPECT_EQ(ch.state.pressure.values(), before.pressure.values());
  // The same model, not failing, does move the iterate in one step: the check above could fail.
  FailingGas<SingularSystem> fine;
  fine.failAt = -1;
  ASSERT_TRUE(advance(ch.state, 1e-3, fine, ch.boundaries, SimpleSettings{}).converged);
  EXPECT_NE(ch.state.phases[0].velocity[0].values(), before.phases[0].velocity[0].values());
}

TEST(SimpleStep, AnyOtherErrorPropagatesAndLeavesTheLastLevel) {
  Channel ch;
  const FlowState before = ch.state;
  EXPECT_THROW((void)advance(ch.state, 1e-3, FailingGas<Error>{}, ch.boundaries, SimpleSettings{}), Error);
  EXPECT_EQ(ch.state.phases[0].velocity[0].values(), before.phases[0].velocity[0].values());
  EXPECT_EQ(ch.state.pressure.values(), before.pressure.values());
}
