// The particle-engine list the dem stage reads (engines/particle_engines): every engine is
// listed whether or not this build has it, an engine it lacks says why, the names the stage
// accepts come from the list, and an engine started and restored through the list continues
// the same run.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/Error.hpp"
#include "engines/lammps/LammpsInput.hpp"
#include "engines/particle_engines/ParticleEngines.hpp"
#include "tests/engines/dem/DemTestSupport.hpp"
#include "tests/support/TempDir.hpp"

namespace pe = grainbridge::particle_engines;
using namespace grainbridge;

TEST(ParticleEngines, GrainbridgeIsFirstAndLammpsIsListedWithOrWithoutTheLibrary) {
  EXPECT_EQ(pe::particleEngineNames(), (std::vector<std::string>{"grainbridge", "lammps"}));
  const auto& own = pe::particleEngine("grainbridge");
  EXPECT_TRUE(own.unavailable().empty());
  EXPECT_TRUE(own.preparation);
  EXPECT_FALSE(own.severalRanks);
  const auto& lmp = pe::particleEngine("lammps");
  EXPECT_TRUE(lmp.severalRanks);
  EXPECT_FALSE(lmp.preparation);
  // Off in this build: it says why and what to install; on: nothing to say.
  if (lammps::lammpsAvailable()) {
    EXPECT_TRUE(lmp.unavailable().empty()) << lmp.unavailable();
  } else {
    EXPECT_NE(lmp.unavailable().find("liblammps-dev"), std::string::npos) << lmp.unavailable();
  }
}

TEST(ParticleEngines, AnUnknownNameIsRefusedNamingTheKnownOnes) {
  try {
    (void)pe::particleEngine("mercurydpm");
    FAIL() << "accepted an unknown engine";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("\"mercurydpm\""), std::string::npos) << what;
    EXPECT_NE(what.find("grainbridge, lammps"), std::string::npos) << what;
  }
}

TEST(ParticleEngines, LammpsRefusalsComeThroughTheList) {
  // A tangential law LAMMPS has no counterpart of with friction on (docs/dem.md): refused by
  // engine lammps, accepted by grainbridge's.
  dem::SimulationSetup setup = dem::testing::openBox(dem::testing::table61Particle());
  const std::vector<double> radii{0.5};
  EXPECT_TRUE(pe::particleEngine("grainbridge").problems(setup, radii).empty());
  const auto listed = pe::particleEngine("lammps").problems(setup, radii);
  const auto direct = lammps::lammpsProblems(setup, {radii});
  ASSERT_FALSE(direct.empty()) << "Table 6.1's projected history with friction is grainbridge's own";
  ASSERT_EQ(listed.size(), direct.size());
  for (std::size_t k = 0; k < listed.size(); ++k) {
    EXPECT_EQ(listed[k].pointer, direct[k].pointer);
    EXPECT_EQ(listed[k].message, direct[k].message);
  }
}

TEST(ParticleEngines, GrainbridgesEngineRestoredThroughTheListContinuesTheRun) {
  const grainbridge::testing::TempDir dir;
  const auto gas = dem::testing::periodicGas(40, 0.2, 1.0, dem::testing::table61Particle(), 2e-4, 7);
  const dem::ParticleEngineStart start{gas.setup, {0.5}, 20, MPI_COMM_NULL, dir.path(), {"key"}};
  const auto& kind = pe::particleEngine("grainbridge");
  auto reference = kind.fresh(start, gas.particles);
  auto stopped = kind.fresh(start, gas.particles);
  for (int s = 0; s < 10; ++s) {
    reference->advance(false);
    stopped->advance(false);
  }
  const auto state = dir.path() / "state.h5";
  stopped->saveState(state, "key");
  auto resumed = kind.restore(start, state, "key");
  EXPECT_THROW((void)kind.restore(start, state, "another key"), Error);
  for (int s = 0; s < 10; ++s) {
    reference->advance(s == 9);
    resumed->advance(s == 9);
  }
  ASSERT_EQ(resumed->step(), reference->step());
  const auto& a = reference->frame();
  const auto& b = resumed->frame();
  ASSERT_EQ(a.position.size(), b.position.size());
  for (std::size_t i = 0; i < a.position.size(); ++i) EXPECT_EQ(a.position[i], b.position[i]) << "particle " << i;
}
