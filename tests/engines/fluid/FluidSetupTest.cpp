// The fluid set-up (fluid::FluidSetup): its JSON form round-trips with the mfm stage's key names,
// each rule that makes a set-up unusable is named by the JSON pointer of its key, and a usable
// set-up becomes the grid's boundary patches (cell ranges, inflow states into the domain).
#include <gtest/gtest.h>

#include "engines/fluid/FluidSetup.hpp"
#include "tests/support/SetupProblems.hpp"

using namespace grainbridge;
using namespace grainbridge::fluid;
using grainbridge::testing::pointersOf;
using nlohmann::json;

namespace {

// A 2D bed of 4 x 16 cells of 1 cm: a jet through the middle of the bottom, an outlet on top.
FluidSetup jetBed() {
  FluidSetup s;
  s.cells = {4, 16, 1};
  s.lengths = Vec3(0.04, 0.16, 0.01);
  s.timeStep.initial = 1e-4;
  s.timeStep.minimum = 1e-7;
  s.timeStep.maximum = 1e-3;
  PatchSetup jet;
  jet.side = "y_low";
  jet.kind = "velocity_inlet";
  jet.from = {0.01, 0.0};
  jet.to = {0.03, 0.0};
  jet.gasInflow = 2.5;
  jet.solidsFractions = {0.1};
  jet.solidsInflow = {0.5};
  PatchSetup outlet;
  outlet.side = "y_high";
  outlet.kind = "pressure_outlet";
  outlet.pressure = 101000.0;
  PatchSetup wall;
  wall.side = "x_low";
  wall.kind = "free_slip_wall";
  s.boundaries = {jet, outlet, wall};
  return s;
}

}  // namespace

TEST(FluidSetup, JsonRoundTripIsExactAndUsesTheStageKeys) {
  const FluidSetup s = jetBed();
  const json j = s;
  const FluidSetup back = j.get<FluidSetup>();
  EXPECT_EQ(json(back), j);
  EXPECT_EQ(back.cells, s.cells);
  EXPECT_EQ(back.lengths, s.lengths);
  EXPECT_EQ(back.timeStep.maximum, s.timeStep.maximum);
  ASSERT_EQ(back.boundaries.size(), 3u);
  EXPECT_EQ(back.boundaries[0].to, s.boundaries[0].to);
  EXPECT_FALSE(back.boundaries[1].from.has_value());  // the whole side stays the whole side
  for (const char* key : {"cells", "lengths", "boundaries", "dt", "dt_min", "dt_max", "courant"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  for (const char* key : {"side", "kind", "from", "to", "gas_inflow", "solids_fractions", "solids_inflow", "pressure"}) {
    EXPECT_TRUE(j.at("boundaries").at(0).contains(key)) << key;
  }
  EXPECT_FALSE(j.at("boundaries").at(1).contains("from"));
}

TEST(FluidSetup, AUsableSetupHasNoProblemAndBecomesGridPatches) {
  const FluidSetup s = jetBed();
  EXPECT_TRUE(s.problems(1, 0.6).empty());
  EXPECT_EQ(s.geometry().spacing[1], 0.01);
  const auto patches = s.patches(1);
  ASSERT_EQ(patches.size(), 3u);
  // The jet covers cells 1 and 2 along x; the 2D grid's z range is its one cell.
  EXPECT_EQ(patches[0].kind, BoundaryKind::VelocityInlet);
  EXPECT_EQ(patches[0].side, YLow);
  EXPECT_EQ(patches[0].from, (std::array<int, 2>{1, 0}));
  EXPECT_EQ(patches[0].to, (std::array<int, 2>{3, 1}));
  ASSERT_EQ(patches[0].phases.size(), 2u);
  EXPECT_DOUBLE_EQ(patches[0].phases[0].fraction, 0.9);
  EXPECT_EQ(patches[0].phases[0].velocity, Vec3(0.0, 2.5, 0.0));
  EXPECT_EQ(patches[0].phases[1].velocity, Vec3(0.0, 0.5, 0.0));
  // An outlet on the high side: backflow speeds point down, into the domain.
  EXPECT_EQ(patches[1].to, (std::array<int, 2>{-1, -1}));
  EXPECT_EQ(patches[1].pressure, 101000.0);
  EXPECT_EQ(patches[1].phases.size(), 2u);
  EXPECT_TRUE(patches[2].phases.empty());  // walls carry no inflow state
}

TEST(FluidSetup, EachPatchRuleNamesItsKey) {
  FluidSetup s = jetBed();
  s.boundaries[2].side = "z_low";  // a 2D grid has no z sides
  EXPECT_EQ(pointersOf(s.problems(1, 0.6)), (std::vector<std::string>{"/boundaries/2/side"}));
  s = jetBed();
  s.boundaries[0].to.reset();
  EXPECT_EQ(pointersOf(s.problems(1, 0.6)), (std::vector<std::string>{"/boundaries/0"}));
  s = jetBed();
  s.boundaries[0].to = {0.05, 0.0};  // past the 4 cm side
  EXPECT_EQ(pointersOf(s.problems(1, 0.6)), (std::vector<std::string>{"/boundaries/0/to"}));
  s = jetBed();
  s.boundaries[0].from = {0.015, 0.0};  // half a cell
  EXPECT_EQ(pointersOf(s.problems(1, 0.6)), (std::vector<std::string>{"/boundaries/0/from"}));
  s = jetBed();
  s.boundaries[0].solidsFractions = {0.1, 0.1};
  s.boundaries[0].solidsInflow = {0.5, 0.5, 0.5};
  EXPECT_EQ(pointersOf(s.problems(1, 0.6)),
            (std::vector<std::string>{"/boundaries/0/solids_fractions", "/boundaries/0/solids_inflow"}));
  s = jetBed();
  s.boundaries[0].solidsFractions = {0.7};
  const auto packed = s.problems(1, 0.6);
  ASSERT_EQ(pointersOf(packed), (std::vector<std::string>{"/boundaries/0/solids_fractions"}));
  EXPECT_NE(packed[0].message.find("above the packed solids fraction 0.6"), std::string::npos) << packed[0].message;
  EXPECT_NE(packed[0].message.find("packed_solids_fraction"), std::string::npos) << packed[0].message;
  // A negative feed speed, and solids given to a wall (which would drop them silently).
  s = jetBed();
  s.boundaries[0].solidsFractions = {0.1};
  s.boundaries[0].solidsInflow = {-0.5};
  EXPECT_EQ(pointersOf(s.problems(1, 0.6)), (std::vector<std::string>{"/boundaries/0/solids_inflow/0"}));
  s = jetBed();
  ASSERT_EQ(s.boundaries[2].kind, "free_slip_wall");
  s.boundaries[2].solidsFractions = {0.1};
  s.boundaries[2].solidsInflow = {0.5};
  const auto wall = s.problems(1, 0.6);
  ASSERT_EQ(pointersOf(wall),
            (std::vector<std::string>{"/boundaries/2/solids_fractions", "/boundaries/2/solids_inflow"}));
  EXPECT_NE(wall[0].message.find("velocity_inlet"), std::string::npos) << wall[0].message;
  // The granular temperature an inflow carries: an inlet's, one per phase, not negative.
  s = jetBed();
  s.boundaries[0].solidsTemperature = {0.01};
  EXPECT_TRUE(s.problems(1, 0.6).empty());
  EXPECT_EQ(s.patches(1)[0].phases[1].granularTemperature, 0.01);
  EXPECT_LT(jetBed().patches(1)[0].phases[1].granularTemperature, 0.0);  // none stated
  s.boundaries[0].solidsTemperature = {-0.01};
  s.boundaries[1].solidsTemperature = {0.01};
  EXPECT_EQ(pointersOf(s.problems(1, 0.6)),
            (std::vector<std::string>{"/boundaries/0/solids_temperature/0", "/boundaries/1/solids_temperature"}));
  s = jetBed();
  s.boundaries[2].side = "y_low";  // over the jet
  const auto overlap = s.problems(1, 0.6);
  EXPECT_EQ(pointersOf(overlap), (std::vector<std::string>{"/boundaries"}));
}

TEST(FluidSetup, AFixedStepRefusesAnInletAboveTheCourantLimit) {
  FluidSetup s = jetBed();
  s.timeStep.minimum = s.timeStep.maximum = s.timeStep.initial = 4e-3;  // 2.5 m/s x 4 ms / 1 cm = 1 cell
  const auto problems = s.problems(1, 0.6);
  ASSERT_EQ(pointersOf(problems), (std::vector<std::string>{"/boundaries/0/gas_inflow"}));
  EXPECT_NE(problems[0].message.find("above the Courant limit 0.5"), std::string::npos) << problems[0].message;
  s.timeStep.minimum = 1e-7;  // an adaptive step keeps itself below the limit
  s.timeStep.initial = 1e-4;
  EXPECT_TRUE(s.problems(1, 0.6).empty());
}

// An engine whose gas step is one fixed key (tfdem's fluid_dt) gets its time-step problems at that
// key and the advice to lower it; mfm's adaptive keys get the advice to let it adapt.
TEST(FluidSetup, AFixedStepKeyTakesTheStepsProblemsAndItsAdvice) {
  FluidSetup s = jetBed();
  s.timeStep.minimum = s.timeStep.maximum = s.timeStep.initial = 4e-3;
  const auto adaptive = s.problems(1, 0.6);
  ASSERT_EQ(adaptive.size(), 1u);
  EXPECT_NE(adaptive[0].message.find(": lower dt or let it adapt (dt_min < dt_max)"), std::string::npos)
      << adaptive[0].message;
  s.fixedStepKey = "fluid_dt";
  const auto fixed = s.problems(1, 0.6);
  ASSERT_EQ(pointersOf(fixed), (std::vector<std::string>{"/boundaries/0/gas_inflow"}));
  EXPECT_TRUE(fixed[0].message.ends_with(": lower fluid_dt")) << fixed[0].message;
  s.timeStep.initial = s.timeStep.minimum = s.timeStep.maximum = 0.0;  // dt, dt_min and dt_max are one key
  for (const auto& problem : s.problems(1, 0.6)) {
    if (!problem.pointer.starts_with("/boundaries")) {
      EXPECT_EQ(problem.pointer, "/fluid_dt") << problem.message;
    }
  }
}

TEST(FluidSetup, TimeStepAndGridProblemsNameTheirKeys) {
  FluidSetup s = jetBed();
  s.timeStep.minimum = 2e-3;  // above dt_max
  const auto problems = s.problems(1, 0.6);
  ASSERT_EQ(pointersOf(problems), (std::vector<std::string>{"/dt_min"}));
  EXPECT_NE(problems[0].message.find("dt_min = 0.002 s is above dt_max = 0.001 s"), std::string::npos)
      << problems[0].message;
  s = jetBed();
  s.timeStep.initial = 1.0;  // the other limits' problems stay at /dt
  EXPECT_EQ(pointersOf(s.problems(1, 0.6)), (std::vector<std::string>{"/dt"}));
  s = jetBed();
  s.lengths[0] = 0.0;
  EXPECT_EQ(pointersOf(s.problems(1, 0.6)), (std::vector<std::string>{"/lengths/0"}));
}
