// `grainbridge closures` (the catalog, docs/closures.md) and `grainbridge closures eval`: the
// calculator evaluates a law through engines/closures with units, and refuses bad names,
// unknown keys, missing inputs and values a law cannot take with exit code 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/Cli.hpp"

using namespace grainbridge::testing;
using ::testing::HasSubstr;

namespace {

CommandResult closures(const std::string& args) { return runCommand(grainbridgeBinary() + " closures " + args); }

TEST(ClosuresCli, EffectiveRestitutionOfTable51) {
  const auto r = closures("eval effective_restitution e=0.97 mu=0.15 beta0=0.33");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("e_eff = 0.82543887"));
}

TEST(ClosuresCli, UnitsAndJsonOutput) {
  // The same bed in mm and in m gives the same beta.
  const auto mm = closures(
      "eval syamlal_obrien void_fraction=0.417 solid_fraction=0.583 'diameter=2.49 mm' slip=2.9 "
      "--format json");
  const auto m = closures(
      "eval syamlal_obrien void_fraction=0.417 solid_fraction=0.583 diameter=0.00249 slip=2.9 "
      "--format json");
  ASSERT_EQ(mm.exitCode, 0) << mm.output;
  ASSERT_EQ(m.exitCode, 0) << m.output;
  const auto a = nlohmann::json::parse(mm.output);
  const auto b = nlohmann::json::parse(m.output);
  EXPECT_NEAR(a["outputs"]["beta"]["value"].get<double>(), b["outputs"]["beta"]["value"].get<double>(), 1e-9);
  EXPECT_EQ(a["outputs"]["beta"]["unit"], "kg/(m3 s)");
  EXPECT_EQ(a["params"]["c"], 0.8);  // defaults are shown as used
}

TEST(ClosuresCli, AnglesTakeDegreesAndRefuseBareDegrees) {
  const std::string state =
      " critical_void_fraction=0.417 void_fraction=0.407 solid_fraction=0.593 strain_invariant=1e6";
  const auto degrees = closures("eval schaeffer 'internal_friction_angle=30 degree'" + state);
  ASSERT_EQ(degrees.exitCode, 0) << degrees.output;
  EXPECT_THAT(degrees.output, HasSubstr("viscosity = 2.5 Pa s"));  // 1e4 Pa x sin 30 / (2 x 1e3)
  const auto bare = closures("eval schaeffer internal_friction_angle=30" + state);
  EXPECT_EQ(bare.exitCode, 2);
  EXPECT_THAT(bare.output, HasSubstr("write \"30 degree\" for degrees"));
}

TEST(ClosuresCli, BadRequestsExitTwoWithTheReason) {
  auto r = closures("eval wen_yu");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.output, HasSubstr("unknown closure \"wen_yu\""));
  r = closures("eval effective_restitution e=0.97");  // mu missing
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.output, HasSubstr("missing required parameter \"mu\""));
  r = closures("eval effective_restitution e=0.97 mu=0.1 nu=2");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.output, HasSubstr("unknown parameter or input \"nu\""));
  r = closures("eval carnahan_starling solid_fraction=1.5");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.output, HasSubstr("solid_fraction"));
  r = closures("eval syamlal_obrien c=0.8 d=3 void_fraction=0.5 solid_fraction=0.5 diameter=0.001 slip=1");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.output, HasSubstr("Eq. 3.14"));
  // The gas and the solids share the volume (issue 54: 0.6 + 0.7 was evaluated).
  r = closures("eval syamlal_obrien void_fraction=0.6 solid_fraction=0.7 diameter=0.001 slip=1");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.output, HasSubstr("solid_fraction 0.7 + void_fraction 0.6 = 1.3: the volume fractions of one point add "
                                  "up to at most 1"));
}

// docs/closures.md is generated from the catalog; it must not drift from it.
TEST(ClosuresCli, DocsMatchTheCatalog) {
  const auto r = closures("--markdown");
  ASSERT_EQ(r.exitCode, 0);
  EXPECT_EQ(readText(sourceDir() / "docs/closures.md"), r.output)
      << "docs/closures.md is out of date: regenerate it with `grainbridge closures --markdown > docs/closures.md`";
  for (const char* law : {"syamlal_obrien", "ergun_wen_yu", "gidaspow", "solids_drag", "carnahan_starling", "lebowitz",
                          "ma_ahmadi_g0", "lun1984", "syamlal_algebraic", "syamlal_algebraic_mfix", "schaeffer",
                          "johnson_jackson", "effective_restitution"}) {
    EXPECT_THAT(r.output, HasSubstr(std::string("## `") + law + "`")) << law;
  }
}

}  // namespace
