// The DEM engine's parameters (dem::SimulationSetup): their JSON form round-trips exactly, and
// each rule that makes a setup unusable is written once, named by the JSON pointer of its key,
// and enforced by the engine itself as well as reported by the dem stage at load.
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "engines/dem/Simulation.hpp"
#include "tests/engines/dem/DemTestSupport.hpp"
#include "tests/support/SetupProblems.hpp"

using namespace grainbridge;
using namespace grainbridge::dem;
using grainbridge::testing::pointersOf;
using nlohmann::json;

namespace {

SimulationSetup twoSpeciesWithWalls() {
  SimulationSetup s = dem::testing::openBox(dem::testing::table61Particle(), 2, 1.7e-4);
  s.lo = Vec3(-1.5, 0, 0.25);
  s.hi = Vec3(7, 6.5, 11);
  s.periodic = {true, false, true};
  s.gravity = Vec3(0.1, 0, -9.81);
  s.backgroundDamping = 0.02;
  s.skin = 0.3;
  s.contact = {"hertz", "dimensional", "lammps_history"};
  s.pairMaterial[1].mu = 0.1;  // one pair differs
  s.pairMaterial[2].mu = 0.1;
  Wall cylinder = dem::testing::floorWall(dem::testing::table61Wall(0.3), 0.0, 2);
  cylinder.kind = Wall::Kind::Cylinder;
  cylinder.radius = 2.5;
  cylinder.vibration = {Vec3(0, 0.6, 0.8), 0.01, 15.0, Vibration::Start::AtRest};
  s.walls = {dem::testing::floorWall(dem::testing::table61Wall(), 0.25, 2), cylinder};
  return s;
}

TEST(SimulationSetup, JsonRoundTripIsExact) {
  const SimulationSetup s = twoSpeciesWithWalls();
  const json j = s;
  const SimulationSetup back = j.get<SimulationSetup>();
  EXPECT_EQ(json(back), j);
  EXPECT_EQ(back.lo, s.lo);
  EXPECT_EQ(back.walls[1].vibration.direction, s.walls[1].vibration.direction);
  EXPECT_EQ(back.walls[1].vibration.start, Vibration::Start::AtRest);
  EXPECT_EQ(back.walls[0].vibration.start, Vibration::Start::MidStroke);
  // The default start is not written, so a state from before the key reads as it did.
  EXPECT_FALSE(j.at("walls")[0].contains("vibration_start"));
  EXPECT_EQ(back.material(0, 1).mu, 0.1);
  EXPECT_EQ(back.contact, s.contact);
  // The keys the dem stage's params share keep the stage's names, so pointers map one to one.
  for (const char* key : {"box_lo", "box_hi", "periodic", "gravity", "shear_rate", "dt", "planar", "normal_model"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j.at("periodic"), "xz");
}

TEST(SimulationSetup, AUsableSetupHasNoProblem) { EXPECT_TRUE(twoSpeciesWithWalls().problems(1.0).empty()); }

TEST(SimulationSetup, EachRuleNamesItsKey) {
  SimulationSetup s = twoSpeciesWithWalls();
  s.hi[0] = s.lo[0] + 2.0;  // periodic along x: 2 < 2 x (1 + 0.3)
  s.shearRate = 5.0;        // y is not periodic
  EXPECT_EQ(pointersOf(s.problems(1.0)), (std::vector<std::string>{"/box_hi/0", "/shear_rate"}));
  s = twoSpeciesWithWalls();
  s.hi[2] = s.lo[2];
  s.dt = 0.0;
  EXPECT_EQ(pointersOf(s.problems(1.0)), (std::vector<std::string>{"/dt", "/box_hi/2"}));
  s = twoSpeciesWithWalls();
  s.walls[0].material.pop_back();
  EXPECT_EQ(pointersOf(s.problems(1.0)), (std::vector<std::string>{"/walls/0"}));
  s = twoSpeciesWithWalls();
  s.contact.tangential = "rolling";
  const auto problems = s.problems(1.0);
  EXPECT_EQ(pointersOf(problems), (std::vector<std::string>{"/tangential_model"}));
  EXPECT_NE(problems.at(0).message.find("registered: history, lammps_history"), std::string::npos)
      << problems.at(0).message;
}

TEST(SimulationSetup, ARunWithoutParticlesIsRefusedAtTheSpeciesWhenTheCountIsKnown) {
  const SimulationSetup s = twoSpeciesWithWalls();
  EXPECT_EQ(pointersOf(s.problems(1.0, 0)), (std::vector<std::string>{"/species"}));
  EXPECT_TRUE(s.problems(1.0, 1).empty());
  EXPECT_TRUE(s.problems(1.0).empty());  // read from a file: not known before the run
}

TEST(SimulationSetup, ANeighbourGridTooLargeToAllocateIsRefusedNamingTheBox) {
  SimulationSetup s = twoSpeciesWithWalls();
  s.hi = s.lo + Vec3::Constant(1.0e4);  // 10^4 diameters per side: 5.9e11 cells
  const auto problems = s.problems(1.0);
  ASSERT_EQ(pointersOf(problems), (std::vector<std::string>{"/box_hi"}));
  EXPECT_NE(problems[0].message.find("neighbour grid over this box would have"), std::string::npos);
  // The engine refuses it the same way, before allocating anything.
  Particles p;
  p.addOwned(0, 0, 0.5, 1.0, s.lo + Vec3::Constant(3.0), Vec3::Zero(), Vec3::Zero(), false);
  try {
    Simulation sim(s, p);
    FAIL() << "a grid of 5.9e11 cells must be refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/box_hi: the neighbour grid"), std::string::npos) << e.what();
  }
}

}  // namespace

// at_rest: A (1 - cos 2 pi f t), at rest at t = 0 and 2 A out at half a period; mid_stroke:
// A sin(2 pi f t), at full speed 2 pi f A at t = 0.
TEST(Vibration, StartsAtRestOrMidStroke) {
  Vibration v{Vec3(0, 0, 1), 0.01, 15.0, Vibration::Start::AtRest};
  EXPECT_EQ(v.displacement(0.0).norm(), 0.0);
  EXPECT_EQ(v.velocity(0.0).norm(), 0.0);
  EXPECT_NEAR(v.displacement(0.5 / 15.0).z(), 0.02, 1e-15);
  EXPECT_NEAR(v.velocity(0.25 / 15.0).z(), 2 * M_PI * 15.0 * 0.01, 1e-12);
  v.start = Vibration::Start::MidStroke;
  EXPECT_EQ(v.displacement(0.0).norm(), 0.0);
  EXPECT_NEAR(v.velocity(0.0).z(), 2 * M_PI * 15.0 * 0.01, 1e-12);
  EXPECT_NEAR(v.displacement(0.25 / 15.0).z(), 0.01, 1e-15);
  EXPECT_EQ(vibrationStartFromName(vibrationStartName(Vibration::Start::AtRest)), Vibration::Start::AtRest);
  EXPECT_THROW((void)vibrationStartFromName("sine"), Error);
}
