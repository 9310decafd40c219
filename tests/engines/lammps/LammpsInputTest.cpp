// The dem setup as LAMMPS input text (engines/lammps/LammpsInput): coefficients to the bit, walls
// by the side they face, frozen species as their own types, Hertzian coefficients converted to
// LAMMPS's sqrt(delta R_eff) factor, and every refusal at the key that causes it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "engines/lammps/LammpsInput.hpp"

using namespace grainbridge;
using grainbridge::lammps::LammpsSpeciesRadii;

namespace {

dem::SimulationSetup twoSpecies() {
  dem::SimulationSetup s;
  s.lo = Vec3(0, 0, 0);
  s.hi = Vec3(0.04, 0.02, 0.06);
  s.periodic = {true, true, false};
  s.gravity = Vec3(0.1, 0, -9.81);
  s.dt = 1e-5;
  s.skin = 3e-4;
  s.contact.tangential = "lammps_history";
  s.species = 2;
  dem::PairMaterial m;
  m.kn = 2e5 / 3.0;  // not a short decimal: must reach LAMMPS to the bit
  m.kt = 2.0 / 7.0 * m.kn;
  m.gammaN = 50.0;
  m.gammaT = 25.0;
  m.mu = 0.5;
  s.pairMaterial.assign(4, m);
  dem::Wall floor;
  floor.origin = Vec3(0, 0, 0.001);
  floor.direction = Vec3(0, 0, 1);
  floor.material.assign(2, m);
  dem::Wall lid = floor;
  lid.origin = Vec3(0, 0, 0.05);
  lid.direction = Vec3(0, 0, -2);  // not normalised: the side it faces is what counts
  s.walls = {floor, lid};
  return s;
}

bool has(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

std::vector<std::string> pointers(const dem::SimulationSetup& s, const LammpsSpeciesRadii& r) {
  std::vector<std::string> out;
  for (const auto& p : lammps::lammpsProblems(s, r)) out.push_back(p.pointer);
  return out;
}

}  // namespace

TEST(LammpsInput, CoefficientsReachLammpsToTheBit) {
  const auto s = twoSpecies();
  const auto in = lammps::lammpsInput(s, {{0.0005, 0.001}}, true);
  const auto& pair = in.interactions.front();
  ASSERT_EQ(pair.rfind("pair_style gran/hooke/history ", 0), 0u) << pair;
  // k_n is printed so that it reads back as the same double.
  const auto kn = std::strtod(pair.c_str() + std::string("pair_style gran/hooke/history ").size(), nullptr);
  EXPECT_EQ(kn, s.material(0, 0).kn);
  EXPECT_TRUE(pair.ends_with(" 50 25 0.5 1")) << pair;  // gamma_n gamma_t mu, tangential damping on
  EXPECT_EQ(in.atomTypes, 4);
  EXPECT_TRUE(has(in.system, "boundary p p f"));
  EXPECT_TRUE(has(in.interactions, "group gb_frozen type 3:4"));
  EXPECT_TRUE(has(in.interactions, "neigh_modify exclude group gb_frozen gb_frozen"));
  EXPECT_TRUE(has(in.interactions, "fix gb_integrate gb_mobile nve/sphere"));
  // Without frozen atoms, no exclusion (it slows LAMMPS's neighbour build) and all atoms move.
  const auto free = lammps::lammpsInput(s, {{0.0005, 0.001}}, false);
  EXPECT_FALSE(std::any_of(free.interactions.begin(), free.interactions.end(),
                           [](const std::string& l) { return l.find("gb_frozen") != std::string::npos; }));
  EXPECT_TRUE(has(free.interactions, "fix gb_integrate all nve/sphere"));
  const auto gravity = std::find_if(in.interactions.begin(), in.interactions.end(), [](const std::string& l) {
    return l.rfind("fix gb_gravity all gravity ", 0) == 0;
  });
  ASSERT_NE(gravity, in.interactions.end());
  EXPECT_TRUE(gravity->ends_with(" vector 0.1 0 -9.81")) << *gravity;
  EXPECT_EQ(std::strtod(gravity->c_str() + std::string("fix gb_gravity all gravity ").size(), nullptr),
            s.gravity.norm());
}

TEST(LammpsInput, AWallIsTheSideItFaces) {
  const auto in = lammps::lammpsInput(twoSpecies(), {{0.0005, 0.001}}, false);
  auto wall = [&](std::size_t w) { return in.walls.at(w).command; };
  EXPECT_TRUE(wall(0).rfind("fix " + lammps::wallFixId(0) + " all wall/gran ", 0) == 0) << wall(0);
  EXPECT_FALSE(in.walls.at(0).vibrating);
  EXPECT_TRUE(wall(0).ends_with(" zplane 0.001 NULL contacts")) << wall(0);  // a floor: particles above
  EXPECT_TRUE(wall(1).ends_with(" zplane NULL 0.05 contacts")) << wall(1);   // a lid: particles below
}

// LAMMPS's Hertz factor is sqrt(delta a_i a_j / (a_i + a_j)), grainbridge's sqrt(delta / (a_i +
// a_j)): a factor a apart for one radius a between grains, a sqrt(2) against a wall.
TEST(LammpsInput, HertzianCoefficientsAbsorbTheOtherFactor) {
  auto s = twoSpecies();
  s.contact.normal = "hertz";
  const double a = 0.0005;
  const auto in = lammps::lammpsInput(s, {{a, a}}, false);
  const auto& pair = in.interactions.front();
  ASSERT_EQ(pair.rfind("pair_style gran/hertz/history ", 0), 0u) << pair;
  const double kn = std::strtod(pair.c_str() + std::string("pair_style gran/hertz/history ").size(), nullptr);
  EXPECT_DOUBLE_EQ(kn * std::sqrt(1e-6 * a * a / (2 * a)), s.material(0, 0).kn * std::sqrt(1e-6 / (2 * a)));
  const std::string floor = in.walls.at(0).command;
  const auto at = floor.find("hertz/history ");
  ASSERT_NE(at, std::string::npos) << floor;
  const double knWall = std::strtod(floor.c_str() + at + 14, nullptr);
  EXPECT_DOUBLE_EQ(knWall * std::sqrt(1e-6 * a), s.walls[0].material[0].kn * std::sqrt(1e-6 / (2 * a)));
}

TEST(LammpsInput, EveryRefusalNamesItsKey) {
  const LammpsSpeciesRadii radii{{0.0005, 0.001}};
  EXPECT_TRUE(lammps::lammpsProblems(twoSpecies(), radii).empty());
  auto s = twoSpecies();
  s.contact.tangential = "history";
  s.contact.damping = "dimensional";
  s.contact.normal = "hertz";
  s.planarAxis = 1;
  s.pressureControl.stress = 10.0;
  s.compression.solidFraction = 0.5;
  s.pairMaterial[1].gammaN = 40.0;
  s.pairMaterial[2].gammaN = 40.0;
  s.walls[0].direction = Vec3(0, 1, 1);
  s.walls[1].material[1].mu = 0.2;
  dem::Wall drum;
  drum.kind = dem::Wall::Kind::Cylinder;
  drum.origin = Vec3(0.02, 0.01, 0);
  drum.radius = 0.01;
  drum.vibration.amplitude = 1e-3;
  drum.vibration.frequency = 20.0;
  drum.vibration.direction = Vec3(1, 0, 0);  // zcylinder wiggles along z only
  drum.material = s.walls[1].material;
  drum.material[1] = drum.material[0];
  s.walls.push_back(drum);
  dem::Wall shaker = s.walls[0];
  shaker.direction = Vec3(0, 0, 1);
  shaker.vibration = {Vec3(0, 0.6, 0.8), 1e-3, 20.0};  // oblique
  s.walls.push_back(shaker);
  shaker.vibration = {Vec3(0, 0, 1), 1e-3, 35.0};  // 3 / (4 f dt) = 2142.9 steps: not whole
  s.walls.push_back(shaker);
  const auto found = pointers(s, radii);
  for (const char* key : {"/tangential_model", "/damping_model", "/normal_model", "/planar", "/pressure_control", "/compression",
                          "/pair_contacts", "/walls/0/direction", "/walls/1", "/walls/2", "/walls/2/vibration_direction",
                          "/walls/3/vibration_direction", "/walls/4/vibration_start"}) {
    EXPECT_TRUE(has(found, key)) << key;
  }
}

// fix deform tilts the box at the end of a step: starting one step ahead gives step n + 1's
// forces grainbridge's offset at t_(n+1).
TEST(LammpsInput, AShearedBoxIsTiltedOneStepAhead) {
  auto s = twoSpecies();
  s.walls.clear();
  s.periodic = {true, true, true};
  s.shearRate = 100.0;
  const auto in = lammps::lammpsInput(s, {{0.0005, 0.001}}, true);
  EXPECT_EQ(lammps::leesEdwardsInitialTilt(s), 100.0 * 0.02 * 1e-5);
  EXPECT_TRUE(std::any_of(in.system.begin(), in.system.end(), [&](const std::string& l) {
    return l.rfind("region gb_box prism 0 0.04 0 0.02 0 0.06 ", 0) == 0 && l.ends_with(" 0 0 units box");
  }));
  EXPECT_TRUE(has(in.interactions, "fix gb_shear all deform 1 xy erate 100 remap v"));
}

TEST(LammpsInput, WithoutFrictionAnyTangentialLawWillDo) {
  auto s = twoSpecies();
  s.contact.tangential = "history";
  EXPECT_TRUE(has(pointers(s, {{0.0005, 0.001}}), "/tangential_model"));
  for (auto& m : s.pairMaterial) m.mu = 0.0;
  for (auto& w : s.walls) {
    for (auto& m : w.material) m.mu = 0.0;
  }
  EXPECT_TRUE(lammps::lammpsProblems(s, {{0.0005, 0.001}}).empty());
}

// LAMMPS's wiggle moves a wall as a (1 - cos omega (n - n0) dt) from the step n0 its fix is made
// at. at_rest is that from step 0; mid_stroke's a sin(omega t) is the same three quarters of a
// period on, from a base one amplitude back.
TEST(LammpsInput, AVibratingWallWigglesFromItsOrigin) {
  auto s = twoSpecies();
  s.walls.resize(1);
  s.walls[0].vibration = {Vec3(0, 0, 1), 2e-4, 25.0};  // a period of 4000 steps of 1e-5 s
  auto in = lammps::lammpsInput(s, {{0.0005, 0.001}}, false);
  ASSERT_TRUE(in.walls.at(0).vibrating);
  EXPECT_EQ(in.walls[0].timeOrigin, 3000);
  EXPECT_TRUE(in.walls[0].command.ends_with(" zplane 8e-04 NULL wiggle z 2e-04 0.04 contacts")) << in.walls[0].command;
  s.walls[0].vibration.start = dem::Vibration::Start::AtRest;
  in = lammps::lammpsInput(s, {{0.0005, 0.001}}, false);
  EXPECT_EQ(in.walls.at(0).timeOrigin, 0);
  EXPECT_TRUE(in.walls[0].command.ends_with(" zplane 0.001 NULL wiggle z 2e-04 0.04 contacts")) << in.walls[0].command;
  // Along -z the signed amplitude is negative, and the base is one amplitude up.
  s.walls[0].vibration = {Vec3(0, 0, -1), 2e-4, 25.0};
  in = lammps::lammpsInput(s, {{0.0005, 0.001}}, false);
  const auto& lid = in.walls.at(0).command;
  ASSERT_TRUE(lid.ends_with(" NULL wiggle z -2e-04 0.04 contacts")) << lid;
  EXPECT_EQ(std::strtod(lid.c_str() + lid.find(" zplane ") + 8, nullptr), 0.001 + 2e-4) << lid;
  // Sideways, a plane only moves in itself: its position stays.
  s.walls[0].vibration = {Vec3(1, 0, 0), 2e-4, 25.0};
  in = lammps::lammpsInput(s, {{0.0005, 0.001}}, false);
  EXPECT_TRUE(in.walls.at(0).command.ends_with(" zplane 0.001 NULL wiggle x 2e-04 0.04 contacts"))
      << in.walls[0].command;
  std::int64_t origin = -1;
  EXPECT_FALSE(lammps::wiggleOrigin({Vec3(0, 0, 1), 2e-4, 35.0}, 1e-5, origin));
  EXPECT_TRUE(lammps::wiggleOrigin({Vec3(0, 0, 1), 2e-4, 35.0, dem::Vibration::Start::AtRest}, 1e-5, origin));
  EXPECT_EQ(origin, 0);
}
