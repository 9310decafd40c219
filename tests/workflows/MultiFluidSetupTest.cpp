// The multi-fluid engine's set-up (mfm::MultiFluidSetup) read from the `mfm` stage's resolved
// keys: the binary smoke bed can run, each physics rule of problems() is reported at the key to
// change, and problems() covers every combination the model itself refuses to build, so a run the
// config check passes never reaches the model's throw.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/json/Diagnostics.hpp"
#include "core/units/UnitSystem.hpp"
#include "engines/closures/MixturePacking.hpp"
#include "engines/mfm/InitialRegions.hpp"
#include "engines/mfm/MultiFluidModel.hpp"
#include "engines/mfm/MultiFluidSetup.hpp"
#include "tests/support/Cli.hpp"
#include "tests/support/SetupProblems.hpp"
#include "workflows/stages/MfmStage.hpp"

using namespace grainbridge;
using grainbridge::testing::pointersOf;
using nlohmann::json;

namespace {

// The binary smoke bed's params (two solids phases, Johnson-Jackson walls, Lebowitz g0 by default)
// with `changes` applied, resolved by the mfm stage's schema.
json resolvedBed(const json& changes = json::object()) {
  const json config = json::parse(
      grainbridge::testing::readText(grainbridge::testing::sourceDir() / "configs/goldschmidt-binary-smoke.json"));
  json params = config.at("stages").at("bed").at("params");
  params.merge_patch(changes);
  core::json::Diagnostics d;
  const json resolved =
      workflows::stages::MfmStage().params().resolve(params, {}, core::units::UnitSystem::si(), "/params", d);
  EXPECT_TRUE(d.empty());
  return resolved;
}

bool has(const std::vector<std::string>& pointers, const std::string& p) {
  return std::find(pointers.begin(), pointers.end(), p) != pointers.end();
}

// Whether the model builds: its constructor throws on what it cannot run.
bool modelBuilds(const mfm::MultiFluidParams& params) {
  try {
    const mfm::MultiFluidModel model(params);
    return true;
  } catch (const Error&) {
    return false;
  }
}

}  // namespace

TEST(MultiFluidSetup, TheBinarySmokeBedCanRunAndItsModelBuilds) {
  const auto setup = resolvedBed().get<mfm::MultiFluidSetup>();
  EXPECT_TRUE(setup.problems().empty()) << pointersOf(setup.problems()).front();
  ASSERT_EQ(setup.model.solids.size(), 2u);
  EXPECT_EQ(setup.model.radialDistribution, mfm::RadialDistributionModel::Lebowitz);
  ASSERT_TRUE(setup.model.wall.has_value());
  EXPECT_EQ(setup.model.wall->maxSolidFraction, setup.settings.packedFraction);
  EXPECT_EQ(setup.settings.phaseNames, (std::vector<std::string>{"gas", "small", "large"}));
  EXPECT_FALSE(setup.patches.empty());  // the fluid set-up is usable, so its patches are made
  EXPECT_TRUE(modelBuilds(setup.model));
}

TEST(MultiFluidSetup, CarnahanStarlingWithTwoPhasesIsRefusedAtTheRadialDistribution) {
  const auto setup = resolvedBed({{"radial_distribution", "carnahan_starling"}}).get<mfm::MultiFluidSetup>();
  EXPECT_EQ(pointersOf(setup.problems()), std::vector<std::string>{"/radial_distribution"});
  EXPECT_FALSE(modelBuilds(setup.model));
}

TEST(MultiFluidSetup, TheAlgebraicBalanceRefusesLunRotationPinnedThetaAndWallsEachAtItsKey) {
  const auto setup =
      resolvedBed({{"granular_energy", "algebraic"}, {"rotation_model", true}, {"plastic_theta", "pinned"}})
          .get<mfm::MultiFluidSetup>();
  const auto pointers = pointersOf(setup.problems());
  for (const char* key : {"/granular_energy", "/rotation_model", "/plastic_theta", "/solids_walls"})
    EXPECT_TRUE(has(pointers, key)) << key;
  EXPECT_FALSE(modelBuilds(setup.model));
  // With the Syamlal coefficients, no rotation, solved theta and sticking walls it runs.
  const auto algebraic =
      resolvedBed(
          {{"granular_energy", "algebraic"}, {"kinetic_model", "syamlal_algebraic"}, {"solids_walls", "no_slip"}})
          .get<mfm::MultiFluidSetup>();
  EXPECT_TRUE(algebraic.problems().empty()) << pointersOf(algebraic.problems()).front();
  EXPECT_TRUE(modelBuilds(algebraic.model));
}

TEST(MultiFluidSetup, ATableClosureNeedsOnePhaseItsNamesAPolicyAndThePde) {
  const auto setup =
      resolvedBed({{"closure", "table"}, {"table_quantities", json::array()}}).get<mfm::MultiFluidSetup>();
  const auto pointers = pointersOf(setup.problems());
  for (const char* key : {"/closure", "/closure_table", "/out_of_range", "/table_quantities"})
    EXPECT_TRUE(has(pointers, key)) << key;
  EXPECT_FALSE(has(pointers, "/granular_energy"));  // the smoke bed solves the pde
}

TEST(MultiFluidSetup, MuOfIPlasticTakesOnePhaseAndARheologyAndSchaefferNone) {
  const auto muI = resolvedBed({{"plastic", "mu_i"}}).get<mfm::MultiFluidSetup>();
  EXPECT_EQ(pointersOf(muI.problems()), (std::vector<std::string>{"/plastic", "/rheology"}));
  const auto schaeffer = resolvedBed({{"rheology", "beads"}}).get<mfm::MultiFluidSetup>();
  EXPECT_EQ(pointersOf(schaeffer.problems()), std::vector<std::string>{"/rheology"});
}

TEST(MultiFluidSetup, TheMFiX2003To05MixtureReadsItsPackingAndKineticTheory) {
  json changes = {{"packing_limit", "yu_standish"}, {"mixture_kinetic_theory", "per_phase"}};
  const json config = json::parse(
      grainbridge::testing::readText(grainbridge::testing::sourceDir() / "configs/goldschmidt-binary-smoke.json"));
  json solids = config.at("stages").at("bed").at("params").at("solids");
  for (auto& phase : solids) phase["max_packing"] = 0.583;
  changes["solids"] = solids;
  const auto setup = resolvedBed(changes).get<mfm::MultiFluidSetup>();
  EXPECT_TRUE(setup.problems().empty()) << pointersOf(setup.problems()).front();
  EXPECT_EQ(setup.model.packingLimit, closures::PackingLimit::YuStandish);
  EXPECT_EQ(setup.model.mixtureKineticTheory, mfm::MixtureKineticTheory::PerPhase);
  for (const auto& phase : setup.model.solids) EXPECT_EQ(phase.maxPacking, 0.583);
  EXPECT_TRUE(modelBuilds(setup.model));
  // Unset, each phase packs at MFiX's 0.6 and the limit is the fixed one.
  const auto plain = resolvedBed().get<mfm::MultiFluidSetup>();
  EXPECT_EQ(plain.model.packingLimit, closures::PackingLimit::Fixed);
  EXPECT_EQ(plain.model.solids.front().maxPacking, 0.6);
  EXPECT_EQ(plain.model.mixtureKineticTheory, mfm::MixtureKineticTheory::Summed);
}

TEST(MultiFluidSetup, APackingLimitByCompositionRefusesOneFixedPackedFractionAndPerPhaseNeedsThePde) {
  const auto packed =
      resolvedBed({{"packing_limit", "gera"}, {"packed_solids_fraction", 0.59}}).get<mfm::MultiFluidSetup>();
  EXPECT_EQ(pointersOf(packed.problems()), std::vector<std::string>{"/packed_solids_fraction"});
  const auto algebraic = resolvedBed({{"granular_energy", "algebraic"},
                                      {"kinetic_model", "syamlal_algebraic"},
                                      {"solids_walls", "no_slip"},
                                      {"mixture_kinetic_theory", "per_phase"}})
                             .get<mfm::MultiFluidSetup>();
  EXPECT_EQ(pointersOf(algebraic.problems()), std::vector<std::string>{"/mixture_kinetic_theory"});
}

// What a feed or an initial region may hold follows the packing limit: under one by composition a
// 50/50 Goldschmidt state packs denser than either phase alone (Yu-Standish: eps_g* about 0.385
// against 0.4 at max_packing 0.6), so a region of 0.61 starts there and is refused under the fixed
// limit (1 - 0.417), naming its composition's eps_s,max.
TEST(MultiFluidSetup, AFeedOrRegionMayHoldWhatItsCompositionPacks) {
  const json dense = {{"regions", {{{"lo", {0, 0, 0}}, {"hi", {0.15, 0.15, 0.015}}, {"solids_fractions", {0.305, 0.305}}}}}};
  json byComposition = dense;
  byComposition["packing_limit"] = "yu_standish";
  const json mixedParams = resolvedBed(byComposition);
  const auto mixed = mixedParams.get<mfm::MultiFluidSetup>();
  ASSERT_TRUE(mixed.problems().empty()) << pointersOf(mixed.problems()).front();
  const auto packedOf = mixed.packedFraction();
  const std::vector<double> half{0.3, 0.3}, pure{0.6, 0.0};
  const closures::MixturePacking packing(closures::PackingLimit::YuStandish, 0.417, {1.52e-3, 2.49e-3}, {0.6, 0.6});
  EXPECT_DOUBLE_EQ(packedOf(half), 1.0 - packing.criticalVoidFraction(half));
  EXPECT_GT(packedOf(half), 0.61);
  EXPECT_DOUBLE_EQ(packedOf(pure), 0.6);  // one phase alone: its max_packing
  EXPECT_TRUE(mixedParams.get<mfm::InitialState>().problems(mixed.geometry, 2, packedOf).empty());
  // The fixed limit: one eps_s,max, 1 - critical_void_fraction, for every composition.
  const json fixedParams = resolvedBed(dense);
  const auto fixed = fixedParams.get<mfm::MultiFluidSetup>();
  EXPECT_DOUBLE_EQ(fixed.packedFraction()(half), 1.0 - 0.417);
  const auto refused = fixedParams.get<mfm::InitialState>().problems(fixed.geometry, 2, fixed.packedFraction());
  EXPECT_EQ(pointersOf(refused), std::vector<std::string>{"/regions/0/solids_fractions"});
}
