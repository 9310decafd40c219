// The initial regions of a multi-fluid run (mfm::InitialState): their JSON form round-trips with
// the mfm stage's key names, and a region the run cannot start from is named by the JSON pointer
// of its key: fractions of another count than the phases, solids above packing.
#include <gtest/gtest.h>

#include "engines/mfm/InitialRegions.hpp"
#include "tests/support/SetupProblems.hpp"

using namespace grainbridge;
using namespace grainbridge::mfm;
using grainbridge::testing::pointersOf;
using nlohmann::json;

namespace {

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
  EXPECT_TRUE(s.problems(1, 0.6).empty());
  s.regions[0].solidsFractions = {0.3, 0.3};
  EXPECT_EQ(pointersOf(s.problems(1, 0.6)), (std::vector<std::string>{"/regions/0/solids_fractions"}));
  s = packedBottom();
  s.regions[0].solidsFractions = {0.65};
  EXPECT_EQ(pointersOf(s.problems(1, 0.6)), (std::vector<std::string>{"/regions/0/solids_fractions"}));
}
