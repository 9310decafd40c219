// The superficial gas velocity the inlets impose (engines/fluid/BoundaryFlow): U = sum over the
// velocity inlets of eps_g v_g A_patch, over the cross-section normal to gravity. Fig. 4.5's
// abscissa: a bottom inlet of pure gas gives its speed exactly, so a fluidization curve read
// off the summary is the curve read off the swept inflow, point for point.
#include <gtest/gtest.h>

#include "engines/fluid/BoundaryFlow.hpp"
#include "engines/fluid/FluidSetup.hpp"

using namespace grainbridge;
using namespace grainbridge::fluid;

namespace {

PatchSetup patch(const std::string& side, const std::string& kind, double gasInflow = 0.0) {
  PatchSetup p;
  p.side = side;
  p.kind = kind;
  p.gasInflow = gasInflow;
  return p;
}

FluidSetup bed(std::array<int, 3> cells, const Vec3& lengths, std::vector<PatchSetup> boundaries) {
  FluidSetup s;
  s.cells = cells;
  s.lengths = lengths;
  s.boundaries = std::move(boundaries);
  return s;
}

double superficial(const FluidSetup& s, const Vec3& gravity, std::size_t solidsPhases = 1) {
  return superficialGasVelocity(s.patches(solidsPhases), s.geometry(), verticalAxis(gravity));
}

}  // namespace

// The shipped beds' case: one pure-gas inlet over the whole bottom, an outlet on top. The areas
// cancel without round-off, on lengths with no exact binary form and whatever the speed.
TEST(SuperficialGasVelocity, AWholeBottomInletOfPureGasGivesItsSpeedExactly) {
  for (const double v : {0.207, 0.414, 0.621, 0.9315, 1.035, 0.1035, 1.92, 2.56, 1.3, 0.2 + 0.1}) {
    // The grain bed of Chapter 4 (2D, gravity along -y).
    const FluidSetup grain = bed({4, 16, 1}, Vec3(0.0381, 0.1524, 0.009525),
                                 {patch("y_low", "velocity_inlet", v), patch("y_high", "pressure_outlet"),
                                  patch("x_low", "no_slip_wall"), patch("x_high", "no_slip_wall")});
    EXPECT_EQ(superficial(grain, Vec3(0.0, -9.81, 0.0)), v) << v;
    // A 3D column with gravity along -z, its inlet on z_low.
    const FluidSetup column = bed({3, 5, 7}, Vec3(0.033, 0.047, 0.31),
                                  {patch("z_low", "velocity_inlet", v), patch("z_high", "pressure_outlet")});
    EXPECT_EQ(superficial(column, Vec3(0.0, 0.0, -9.81)), v) << v;
    // Gravity along +y: the bottom is y_high, and its inlet blows the gas in along -y, upwards.
    const FluidSetup upsideDown = bed({4, 16, 1}, Vec3(0.0381, 0.1524, 0.009525),
                                      {patch("y_high", "velocity_inlet", v), patch("y_low", "pressure_outlet")});
    EXPECT_EQ(superficial(upsideDown, Vec3(0.0, 9.81, 0.0)), v) << v;
  }
}

// A jet over part of the bottom carrying solids: its gas volume flow eps_g v_g A_jet spread over
// the bottom. Here eps_g = 0.9 and the jet covers 2 of the 4 cm: U = 0.9 * 2.5 * 0.5.
TEST(SuperficialGasVelocity, AJetCountsItsGasShareOverItsShareOfTheBottom) {
  PatchSetup jet = patch("y_low", "velocity_inlet", 2.5);
  jet.from = {0.01, 0.0};
  jet.to = {0.03, 0.0};
  jet.solidsFractions = {0.1};
  jet.solidsInflow = {0.5};
  const FluidSetup s = bed({4, 16, 1}, Vec3(0.04, 0.16, 0.01), {jet, patch("y_high", "pressure_outlet")});
  EXPECT_DOUBLE_EQ(superficial(s, Vec3(0.0, -9.81, 0.0)), 0.9 * 2.5 * 0.5);
}

// Every inlet adds its volume flow, whatever side it is on: a side inlet of 0.1 m/s over the
// 0.16 m high x_low side of a 0.04 m wide bed adds 0.1 * 0.16 / 0.04 to the bottom's 1 m/s. A
// pressure outlet's backflow state is not an imposed flow and walls carry none.
TEST(SuperficialGasVelocity, SideInletsAddTheirFlowAndOutletsAndWallsNone) {
  PatchSetup outlet = patch("y_high", "pressure_outlet", 3.0);  // gas flowing back in at 3 m/s
  const FluidSetup s = bed({4, 16, 1}, Vec3(0.04, 0.16, 0.01),
                           {patch("y_low", "velocity_inlet", 1.0), patch("x_low", "velocity_inlet", 0.1), outlet,
                            patch("x_high", "free_slip_wall")});
  EXPECT_DOUBLE_EQ(superficial(s, Vec3(0.0, -9.81, 0.0)), 1.0 + 0.1 * 0.16 / 0.04);
  const FluidSetup closed = bed({4, 16, 1}, Vec3(0.04, 0.16, 0.01), {outlet, patch("y_low", "no_slip_wall")});
  EXPECT_EQ(superficial(closed, Vec3(0.0, -9.81, 0.0)), 0.0);
}
