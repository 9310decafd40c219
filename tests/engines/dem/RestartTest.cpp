// Exact restart (issue 4, VALIDATION.md DEM): a run continued from a captured state reproduces
// the uninterrupted run bit for bit on the same binary, in a dense frictional packing where
// contact history, neighbour rebuilds, re-sorting and periodic images all matter.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <type_traits>

#include <filesystem>

#include "core/io/CheckpointFile.hpp"
#include "engines/dem/Checkpoint.hpp"
#include "engines/dem/Insertion.hpp"
#include "tests/engines/dem/DemTestSupport.hpp"
#include "tests/support/ValidationRecord.hpp"

using namespace grainbridge;
using namespace grainbridge::dem;
using namespace grainbridge::dem::testing;

namespace {

SimulationSetup packingSetup() {
  SimulationSetup s = openBox(table61Particle());
  s.lo = Vec3(0, 0, 0);
  s.hi = Vec3(8, 8, 30);
  s.periodic = {true, true, false};
  s.gravity = Vec3(0, 0, -1);
  s.sortEveryRebuilds = 2;  // exercise re-sorting often
  s.walls.push_back(floorWall(table61Wall()));
  return s;
}

Particles packingParticles() {
  InsertionRequest rq;
  rq.lo = Vec3(0, 0, 0);
  rq.hi = Vec3(8, 8, 20);
  rq.periodic = {true, true, false};
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> size(0.45, 0.55);  // polydisperse radii
  for (int i = 0; i < 400; ++i) rq.radii.push_back(size(rng));
  const auto centres = insertRandomly(rq, rng);
  Particles p;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const double a = rq.radii[i];
    p.addOwned(static_cast<std::int64_t>(i), 0, a, sphereMass(2 * a, 1.91), centres[i], Vec3(0.1, -0.2, 0),
               Vec3::Zero(), false);
  }
  return p;
}

void expectBitwiseEqual(const Simulation& a, const Simulation& b) {
  ASSERT_EQ(a.particles().nOwned, b.particles().nOwned);
  EXPECT_EQ(a.stepCount(), b.stepCount());
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(differingParticles(a, b), 0u);
}

}  // namespace

TEST(Restart, ContinuesBitForBit) {
  Simulation uninterrupted(packingSetup(), packingParticles());
  uninterrupted.run(30000);  // settling (6 t0): many contacts with history, several rebuilds and sorts
  ASSERT_GT(uninterrupted.contactCount(), 50u);
  ASSERT_GT(uninterrupted.rebuilds(), 3);
  // Mid-way between rebuilds, so the restored list must be rebuilt from the build positions.
  const EngineState state = uninterrupted.captureState();
  Simulation resumed(packingSetup(), state);
  uninterrupted.run(5000);
  resumed.run(5000);
  expectBitwiseEqual(uninterrupted, resumed);
  if (uninterrupted.particles().nOwned == resumed.particles().nOwned) {  // else the assertion above failed
    const std::size_t differing = differingParticles(uninterrupted, resumed);
    grainbridge::testing::recordValidation(
        {"dem.history.restart", "DEM (Chapter 6)",
         "checkpoint/restart of a settling 400-sphere frictional packing: particles whose position, velocity or "
         "spin differ in any bit from the uninterrupted run 5000 steps later",
         "Eq. 6.4; VALIDATION.md DEM (tangential history)", 0.0, static_cast<double>(differing), "bit for bit",
         differing == 0 && uninterrupted.stepCount() == resumed.stepCount() && uninterrupted.time() == resumed.time(),
         "captured after 30000 steps (mid-way between rebuilds), re-sorting every 2 rebuilds, periodic in x and y"});
  }
}

TEST(Restart, CapturedStateIsIndependentOfOutputRecording) {
  // Output is read-only on contact state: recording contacts every step changes nothing.
  Simulation quiet(packingSetup(), packingParticles());
  Simulation recorded(packingSetup(), packingParticles());
  for (int s = 0; s < 3000; ++s) {
    quiet.step(false);
    recorded.step(true);
  }
  expectBitwiseEqual(quiet, recorded);
}

// The checkpoint file holds every per-particle array Particles declares, by name, exactly: a
// field added to that list (drag, void fraction) survives a restart without touching this code.
TEST(Restart, CheckpointFileHoldsEveryParticleArray) {
  Simulation sim(packingSetup(), packingParticles());
  for (std::size_t i = 0; i < sim.particles().nOwned; ++i) {
    auto& p = sim.mutableParticles();
    p.couplingA[i] = Vec3(1e-3 * static_cast<double>(i), 2.0, -0.5);
    p.couplingB[i] = 0.01 * static_cast<double>(i) + 1.0 / 3.0;
    p.couplingU[i] = Vec3(0.1, 0.2, 1.0 / 7.0);
    p.couplingPressure[i] = Vec3(0.0, 1e-4 * static_cast<double>(i), 0.0);
  }
  sim.run(200);
  const EngineState state = sim.captureState();
  const auto file = std::filesystem::temp_directory_path() / "grainbridge-restart-arrays.ckpt";
  writeCheckpoint(file, state, "fingerprint");
  const EngineState back = readCheckpoint(file, "fingerprint");
  std::filesystem::remove(file);
  ASSERT_EQ(back.particles.nOwned, state.particles.nOwned);
  int arrays = 0;
  auto compare = [&](const char* name, const auto& a) {
    ++arrays;
    bool found = false;
    auto match = [&](const char* otherName, const auto& b) {
      if constexpr (std::is_same_v<std::decay_t<decltype(a)>, std::decay_t<decltype(b)>>) {
        if (std::string(otherName) == name) {
          found = true;
          EXPECT_TRUE(a == b) << name;
        }
      }
    };
    Particles::forEachParticleArray(back.particles, match);
    Particles::forEachOwnedArray(back.particles, match);
    EXPECT_TRUE(found) << name;
  };
  Particles::forEachParticleArray(state.particles, compare);
  Particles::forEachOwnedArray(state.particles, compare);
  EXPECT_EQ(arrays, 15);
}

// A coupled engine (TF-DEM) keeps the DEM state in a group of its checkpoint beside the fluid's:
// the state read from "/dem" equals the one the dem engine's own checkpoint holds at the root.
TEST(Restart, EngineStateInAGroupEqualsTheRootCheckpoint) {
  Simulation sim(packingSetup(), packingParticles());
  sim.run(200);
  const EngineState state = sim.captureState();
  const auto dir = std::filesystem::temp_directory_path();
  const auto root = dir / "grainbridge-restart-root.ckpt";
  const auto coupled = dir / "grainbridge-restart-coupled.ckpt";
  writeCheckpoint(root, state, "fingerprint");
  core::io::writeCheckpointFile(coupled, {1, "coupled"}, [&](core::io::H5OutputFile& f) {
    writeEngineState(f, state, "/dem");
    f.createGroup("/fluid");
    f.writeAttribute("/fluid", "time", 99.0);
  });
  const EngineState fromRoot = readCheckpoint(root, "fingerprint");
  const EngineState fromGroup = readEngineState(core::io::openCheckpointFile(coupled, {1, "coupled"}), "/dem");
  std::filesystem::remove(root);
  std::filesystem::remove(coupled);
  EXPECT_EQ(fromGroup.time, fromRoot.time);
  EXPECT_EQ(fromGroup.step, fromRoot.step);
  EXPECT_EQ(fromGroup.rebuildsSinceSort, fromRoot.rebuildsSinceSort);
  ASSERT_EQ(fromGroup.particles.nOwned, state.particles.nOwned);
  int arrays = 0;
  auto compare = [&](const char* name, const auto& a) {
    auto match = [&](const char* otherName, const auto& b) {
      if constexpr (std::is_same_v<std::decay_t<decltype(a)>, std::decay_t<decltype(b)>>) {
        if (std::string(otherName) == name) {
          ++arrays;
          EXPECT_TRUE(a == b) << name;
        }
      }
    };
    Particles::forEachParticleArray(fromRoot.particles, match);
    Particles::forEachOwnedArray(fromRoot.particles, match);
  };
  Particles::forEachParticleArray(fromGroup.particles, compare);
  Particles::forEachOwnedArray(fromGroup.particles, compare);
  EXPECT_EQ(arrays, 15);
  EXPECT_EQ(fromGroup.buildPositions, fromRoot.buildPositions);
  auto samePair = [](const PairHistory& a, const PairHistory& b) {
    return a.low == b.low && a.high == b.high && a.ut == b.ut;
  };
  EXPECT_TRUE(std::equal(fromGroup.pairHistory.begin(), fromGroup.pairHistory.end(), fromRoot.pairHistory.begin(),
                         fromRoot.pairHistory.end(), samePair));
  EXPECT_EQ(fromGroup.wallHistory, fromRoot.wallHistory);
}
