// A gas-solids drag law is one struct plus one line in a list (docs/adding-a-drag-law.md). This
// file defines a law of its own, TestStokes, appends it to a copy of engines/closures' list, and
// runs that list through every consumer of the list: the choice by name and the variant the
// engines visit once per sweep, the closure catalog's entries (`grainbridge closures` lists and
// evaluates them), and the drag keys of the mfm and tfdem stages (`grainbridge stages`, the
// set-up that reads them back). The same templates, with the registered list, build the shipped
// catalog and stages, which the last tests check against it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "core/json/Diagnostics.hpp"
#include "core/units/UnitSystem.hpp"
#include "engines/closures/GasSolidsDrag.hpp"
#include "workflows/closures/ClosureCatalog.hpp"
#include "workflows/closures/DragLawCatalog.hpp"
#include "workflows/stages/DragSchema.hpp"
#include "workflows/stages/DragSetup.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace gc = grainbridge::closures;
namespace catalog = grainbridge::workflows::closures;
using grainbridge::core::json::Diagnostics;
using grainbridge::core::units::UnitSystem;
using grainbridge::workflows::params::ParamSchema;
using nlohmann::json;
using ::testing::Contains;
using ::testing::HasSubstr;

namespace {

// ---- the one struct ------------------------------------------------------------------------------
// Stokes drag in a swarm with a Richardson-Zaki-like voidage function, beta / eps_s =
// 18 mu_g eps_g^-n / d^2: a lone particle (eps_g 1) feels 3 pi mu_g d, Stokes's sphere.
struct TestStokes {
  struct Params {
    double exponent = 2.65;
  };
  static constexpr const char* name = "test_stokes";
  static constexpr const char* doc = "Stokes drag with a voidage function (a test's law)";
  static constexpr const char* equations = "Eq. 7.29 with beta = 18 mu_g eps_s eps_g^-n / d^2";
  static constexpr const char* source = "Stokes 1851; tests/workflows/DragLawWiringTest.cpp";
  static constexpr std::array<gc::DragParameter<Params>, 1> parameters{
      {{"exponent", &Params::exponent, false, "n of eps_g^-n", "drag_test_exponent"}}};
  static constexpr std::array<gc::DragSwitch, 0> switches{};
  // n above 10 is nothing a swarm does.
  [[nodiscard]] static gc::DragParamsProblem check(const Params& p) {
    return {"exponent", p.exponent > 10.0 ? "n above 10" : ""};
  }

  Params params;
  [[nodiscard]] gc::DragCoefficients evaluate(const gc::DragState& s) const {
    gc::validate(s);
    const double d = s.diameter;
    return gc::dragFromBetaPerSolidFraction(
        s, 18.0 * s.gasViscosity * std::pow(s.voidFraction, -params.exponent) / (d * d));
  }
};
// ---- and the one line ----------------------------------------------------------------------------
using TestLaws = gc::AppendDragLaws<gc::DragLaws, TestStokes>::type;
using TestDrag = gc::GasSolidsDragOf<TestLaws>;

const gc::DragState kLone{1.0, 0.0, 1e-3, 1.2, 1.8e-5, 0.01};

TEST(DragLawWiring, ATestLawIsChosenByNameBesideTheRegisteredOnes) {
  EXPECT_THAT(TestDrag::names(), Contains("test_stokes"));
  for (const auto& name : gc::GasSolidsDrag::names()) EXPECT_THAT(TestDrag::names(), Contains(name));
  const TestDrag drag = TestDrag::byName("test_stokes");
  EXPECT_EQ(drag.name, "test_stokes");
  ASSERT_TRUE(std::holds_alternative<TestStokes>(drag.law));
  // Stokes's 3 pi mu d for a lone particle, through the variant as an engine's sweep reads it:
  // visited once, the loop inside calling the chosen law.
  const double particle = drag.visit([](const auto& law) { return law.evaluate(kLone).particle; });
  EXPECT_NEAR(particle, 3.0 * M_PI * 1.8e-5 * 1e-3, 1e-15);
  EXPECT_THROW((void)TestDrag::byName("test_stoke"), grainbridge::Error);
}

TEST(DragLawWiring, ATestLawGetsACatalogEntry) {
  const auto entries = catalog::dragLawEntries(TestLaws{});
  ASSERT_EQ(entries.size(), gc::GasSolidsDrag::names().size() + 1);
  const catalog::ClosureEntry& e = entries.back();
  EXPECT_EQ(e.name, "test_stokes");
  EXPECT_EQ(e.summary, TestStokes::doc);
  EXPECT_EQ(e.equations, TestStokes::equations);
  EXPECT_EQ(e.source, TestStokes::source);
  const auto* n = e.params->find("exponent");
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(n->defaultJson()->get<double>(), 2.65);
  EXPECT_EQ(n->docText(), "n of eps_g^-n");
  EXPECT_NE(e.inputs->find("void_fraction"), nullptr);
  // `closures eval test_stokes exponent=0 ...`: the resolved params and inputs through the law.
  const json in = {{"void_fraction", 0.5}, {"solid_fraction", 0.5},   {"diameter", 1e-3},
                   {"gas_density", 1.2},   {"gas_viscosity", 1.8e-5}, {"slip", 0.01}};
  const auto out = e.evaluate(json{{"exponent", 0.0}}, in);
  ASSERT_EQ(out.size(), 2U);
  EXPECT_EQ(out[0].name, "beta");
  EXPECT_NEAR(out[0].value, 0.5 * 18.0 * 1.8e-5 / 1e-6, 1e-9);
  EXPECT_EQ(e.checkParams(json{{"exponent", 2.65}}), "");
  EXPECT_EQ(e.checkParams(json{{"exponent", 11.0}}), "n above 10");
}

TEST(DragLawWiring, ATestLawIsAStageOptionWithItsKeys) {
  ParamSchema schema;
  grainbridge::workflows::stages::addDragParams<TestLaws>(schema, "syamlal_obrien", "drag law");
  const auto* drag = schema.find("drag");
  ASSERT_NE(drag, nullptr);
  EXPECT_THAT(drag->typeDescription(), HasSubstr("test_stokes"));
  EXPECT_EQ(drag->defaultJson()->get<std::string>(), "syamlal_obrien");
  ASSERT_NE(schema.find("drag_test_exponent"), nullptr);
  EXPECT_EQ(schema.find("drag_test_exponent")->defaultJson()->get<double>(), 2.65);
  EXPECT_NE(schema.find("drag_c"), nullptr);  // the registered laws' keys stay

  // A config choosing it is resolved, and the set-up reads its key back into the law.
  Diagnostics d;
  const json resolved =
      schema.resolve(json{{"drag", "test_stokes"}, {"drag_test_exponent", 3.0}}, {}, UnitSystem::si(), "/p", d);
  ASSERT_TRUE(d.empty());
  std::vector<std::string> problems;
  const auto report = [&problems](const std::string& key, const std::string& why) {
    problems.push_back(key + ": " + why);
  };
  const TestDrag chosen = grainbridge::workflows::stages::dragFromParams<TestLaws>(resolved, report);
  ASSERT_TRUE(std::holds_alternative<TestStokes>(chosen.law));
  EXPECT_EQ(std::get<TestStokes>(chosen.law).params.exponent, 3.0);
  EXPECT_TRUE(problems.empty());
  // Its check is reported at its stage key.
  (void)grainbridge::workflows::stages::dragFromParams<TestLaws>(
      schema.resolve(json{{"drag", "test_stokes"}, {"drag_test_exponent", 12.0}}, {}, UnitSystem::si(), "/p", d),
      report);
  EXPECT_EQ(problems, std::vector<std::string>{"/drag_test_exponent: n above 10"});
  // An unknown name is refused by the option list before any set-up.
  Diagnostics bad;
  (void)schema.resolve(json{{"drag", "stokes"}}, {}, UnitSystem::si(), "/p", bad);
  EXPECT_FALSE(bad.empty());
}

// The shipped catalog and stages are the same templates over the registered list.
TEST(DragLawWiring, TheCatalogAndBothStagesReadTheRegisteredList) {
  for (const auto& e : catalog::dragLawEntries(gc::DragLaws{})) {
    const catalog::ClosureEntry* shipped = catalog::findClosure(e.name);
    ASSERT_NE(shipped, nullptr) << e.name;
    EXPECT_EQ(shipped->summary, e.summary);
    EXPECT_EQ(shipped->params->names(), e.params->names());
  }
  for (const char* stage : {"mfm", "tfdem"}) {
    const auto* type = grainbridge::workflows::stages::StageRegistry::builtin().find(stage);
    ASSERT_NE(type, nullptr) << stage;
    const auto* drag = type->params().find("drag");
    ASSERT_NE(drag, nullptr) << stage;
    for (const auto& name : gc::GasSolidsDrag::names()) EXPECT_THAT(drag->typeDescription(), HasSubstr(name)) << stage;
    for (const char* key : {"drag_c", "drag_d"}) EXPECT_NE(type->params().find(key), nullptr) << stage << " " << key;
  }
}

}  // namespace
