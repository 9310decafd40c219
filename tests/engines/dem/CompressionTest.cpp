// Compression to a fixed solid fraction (issue 60; SimulationSetup::Compression): a sheared box
// inserted dilute shrinks along y, linearly in time, to the length at which its grains fill the
// target fraction, and holds it. Frictionless spheres, d = m = gammadot = 1, e = 0.9,
// k* = 1e4; inserted at random at 0.3 in a box long along y, so the held box is a cube at 0.55,
// a fraction random insertion cannot reach (it jams near 0.38).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "core/Error.hpp"
#include "engines/dem/Checkpoint.hpp"
#include "tests/engines/dem/DemTestSupport.hpp"

using namespace grainbridge;
using namespace grainbridge::dem;
using namespace grainbridge::dem::testing;

namespace {

constexpr int kParticles = 256;
constexpr double kRho = 6.0 / M_PI;  // m = 1 for d = 1
constexpr double kInserted = 0.3, kTarget = 0.55;
const double kSide = std::cbrt(kParticles * M_PI / 6.0 / kTarget);  // the held cube's side

SimulationSetup compressedBox() {
  const PairMaterial mat = frictionlessUnitMass(1e4 * kRho, 0.9);
  SimulationSetup s = periodicCube(mat, kSide, linearContactTime(mat.kn, mat.gammaN, 0.5) / 50.0, 1.0);
  s.hi[1] = kSide * kTarget / kInserted;  // the same grains fill 0.3 of this box
  s.compression.solidFraction = kTarget;
  s.compression.duration = 5.0;  // strain units
  s.compression.interval = 10;
  return s;
}

Particles shearedGas(const SimulationSetup& s, unsigned seed) {
  std::mt19937_64 rng(seed);
  return shearedUnitSpheres(s, randomCentres(s, kParticles, 0.5, rng));
}

double solidFraction(const Simulation& sim) { return unitSphereSolidFraction(sim, kParticles); }

}  // namespace

TEST(Compression, ShrinksLinearlyInTimeToItsFractionAndThenHoldsIt) {
  const SimulationSetup s = compressedBox();
  Simulation sim(s, shearedGas(s, 5));
  const double startY = s.hi[1];
  // Mid-way, at a box change: the length the schedule gives at that time.
  const auto half = static_cast<std::int64_t>(0.5 * s.compression.duration / s.dt) / 10 * 10;
  sim.run(half);
  const double expected = startY + sim.time() / s.compression.duration * (kSide - startY);
  EXPECT_NEAR(sim.boxHigh()[1], expected, 1e-12 * kSide);
  EXPECT_GT(solidFraction(sim), kInserted);
  EXPECT_LT(solidFraction(sim), kTarget);
  // Past the duration: the target exactly, and the box stays.
  sim.run(static_cast<std::int64_t>(0.6 * s.compression.duration / s.dt));
  EXPECT_NEAR(solidFraction(sim), kTarget, 1e-13);
  const Vec3 held = sim.boxHigh();
  EXPECT_DOUBLE_EQ(held[0], kSide);
  EXPECT_DOUBLE_EQ(held[2], kSide);
  sim.run(1000);
  EXPECT_EQ(sim.boxHigh()[1], held[1]);
  for (std::size_t i = 0; i < sim.particles().nOwned; ++i) {
    EXPECT_GE(sim.particles().x[i][1], 0.0);
    EXPECT_LT(sim.particles().x[i][1], held[1]);
  }
  // Sheared, not jammed: the grains move (T well above zero).
  EXPECT_GT(granularTemperature(sim.particles()), 1e-3);
}

TEST(Compression, ResumedFromItsCheckpointFileContinuesBitForBit) {
  const SimulationSetup s = compressedBox();
  Simulation uninterrupted(s, shearedGas(s, 6));
  uninterrupted.run(10005);  // mid-way between box changes, mid-way through the compression
  ASSERT_NE(uninterrupted.boxHigh()[1], s.hi[1]);
  const auto file = std::filesystem::temp_directory_path() / "grainbridge-compression-restart.ckpt";
  writeCheckpoint(file, uninterrupted.captureState(), "fingerprint");
  Simulation resumed(s, readCheckpoint(file, "fingerprint"));
  std::filesystem::remove(file);
  uninterrupted.run(3000);
  resumed.run(3000);
  EXPECT_EQ(resumed.boxHigh()[1], uninterrupted.boxHigh()[1]);
  EXPECT_EQ(resumed.shearOffset(resumed.time()), uninterrupted.shearOffset(uninterrupted.time()));
  EXPECT_EQ(differingParticles(uninterrupted, resumed), 0u);
}

TEST(Compression, ATargetTheInsertedGrainsAlreadyExceedIsRefused) {
  SimulationSetup s = compressedBox();
  s.compression.solidFraction = 0.25;  // below the inserted 0.3: the box would have to grow
  const SimulationSetup inserted = compressedBox();
  try {
    Simulation sim(s, shearedGas(inserted, 5));
    FAIL() << "a compression that would grow the box ran";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("compression only shrinks"));
  }
}

TEST(Compression, SetupProblemsNameTheKey) {
  auto pointers = [](const SimulationSetup& s) {
    std::vector<std::string> out;
    for (const auto& p : s.problems(1.0)) out.push_back(p.pointer);
    return out;
  };
  using ::testing::Contains;
  const SimulationSetup s = compressedBox();
  EXPECT_TRUE(pointers(s).empty());
  SimulationSetup unsheared = s;
  unsheared.shearRate = 0.0;
  EXPECT_THAT(pointers(unsheared), Contains("/compression"));
  SimulationSetup controlled = s;
  controlled.pressureControl.stress = 10.0;
  controlled.pressureControl.relaxationTime = 1.0;
  EXPECT_THAT(pointers(controlled), Contains("/compression"));
  SimulationSetup solid = s;
  solid.compression.solidFraction = 1.2;
  EXPECT_THAT(pointers(solid), Contains("/compression"));
  SimulationSetup instant = s;
  instant.compression.duration = 0.0;
  EXPECT_THAT(pointers(instant), Contains("/compression/duration"));
}
