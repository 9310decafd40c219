// The initial regions of a multi-fluid run (mfm::InitialState): their JSON form round-trips with
// the mfm stage's key names, and a region the run cannot start from is named by the JSON pointer
// of its key: fractions of another count than the phases, solids above packing, a box partly
// outside the domain (a 2D grid's z against its depth).
#include <gtest/gtest.h>

#include "engines/mfm/InitialRegions.hpp"
#include "tests/support/SetupProblems.hpp"

using namespace grainbridge;
using namespace grainbridge::mfm;
using grainbridge::testing::pointersOf;
using nlohmann::json;

namespace {

// 4 x 16 x 1 cells of 1 cm: a 2D bed 1 cm deep.
core::data::GridGeometry bed2D() {
  core::data::GridGeometry g;
  g.cells = {4, 16, 1};
  g.spacing = Vec3(0.01, 0.01, 0.01);
  return g;
}

InitialState packedBottom() {
  InitialState s;
  InitialRegion bottom;
  bottom.lo = Vec3::Zero();
  bottom.hi = Vec3(0.04, 0.08, 0.01);
  bottom.solidsFractions = {0.55};
  bottom.velocities = {Vec3(0.0, 1.2, 0.0), Vec3(0.0, 0.1, 0.0)};
  bottom.granularTemperature = 1e-3;
  s.regions = {bottom};
  s.referencePressure = 101000.0;
  s.perturbation = 0.02;
  s.seed = 7;
  return s;
}

}  // namespace

TEST(InitialState, JsonRoundTripIsExactAndUsesTheStageKeys) {
  const InitialState s = packedBottom();
  const json j = s;
  const InitialState back = j.get<InitialState>();
  EXPECT_EQ(json(back), j);
  ASSERT_EQ(back.regions.size(), 1u);
  EXPECT_EQ(back.regions[0].hi, s.regions[0].hi);
  EXPECT_EQ(back.regions[0].velocities, s.regions[0].velocities);
  EXPECT_EQ(back.seed, 7u);
  for (const char* key : {"lo", "hi", "solids_fractions", "gas_velocity", "solids_velocity", "granular_temperature"}) {
    EXPECT_TRUE(j.at("regions").at(0).contains(key)) << key;
  }
  // Regions are optional in the stage: none is gas everywhere.
  const InitialState none = json{{"reference_pressure", 1e5}, {"perturbation", 0.0}, {"seed", 1}}.get<InitialState>();
  EXPECT_TRUE(none.regions.empty());
}

TEST(InitialState, EachRegionRuleNamesItsKey) {
  InitialState s = packedBottom();
  EXPECT_TRUE(s.problems(bed2D(), 1, 0.6).empty());
  s.regions[0].solidsFractions = {0.3, 0.3};
  EXPECT_EQ(pointersOf(s.problems(bed2D(), 1, 0.6)), (std::vector<std::string>{"/regions/0/solids_fractions"}));
  s = packedBottom();
  s.regions[0].solidsFractions = {0.65};
  EXPECT_EQ(pointersOf(s.problems(bed2D(), 1, 0.6)), (std::vector<std::string>{"/regions/0/solids_fractions"}));
}

TEST(InitialState, ARegionPartlyOutsideTheDomainIsRefusedAtItsCorner) {
  InitialState s = packedBottom();
  s.regions.push_back(s.regions[0]);
  s.regions[1].lo[0] = -0.01;
  s.regions[1].hi[1] = 0.2;  // above the 16 cm domain
  const auto problems = s.problems(bed2D(), 1, 0.6);
  ASSERT_EQ(pointersOf(problems), (std::vector<std::string>{"/regions/1/lo", "/regions/1/hi"}));
  EXPECT_NE(problems[0].message.find("lo along x is -0.01 m, outside the domain (0 to 0.04 m)"), std::string::npos)
      << problems[0].message;
  EXPECT_NE(problems[1].message.find("hi along y is 0.2 m"), std::string::npos) << problems[1].message;
  // A 2D grid's z extent is its depth.
  s = packedBottom();
  s.regions[0].hi[2] = 0.02;
  EXPECT_EQ(pointersOf(s.problems(bed2D(), 1, 0.6)), (std::vector<std::string>{"/regions/0/hi"}));
  // Corners on the domain's sides, written in other units than the lengths, are inside.
  s = packedBottom();
  s.regions[0].hi = Vec3(4 * 0.01, 16 * 0.01, 0.01) * (1.0 + 1e-12);
  EXPECT_TRUE(s.problems(bed2D(), 1, 0.6).empty());
}
