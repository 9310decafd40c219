#include <gtest/gtest.h>

#include "workflows/params/ParamSchema.hpp"

using namespace grainbridge::workflows::params;
using grainbridge::core::json::Diagnostics;
using grainbridge::core::units::Dimension;
using grainbridge::core::units::UnitSystem;
using nlohmann::json;

namespace {
ParamSchema schema() {
  ParamSchema s;
  s.add(ParamSpec::quantity("dt", Dimension::timeDim()).required().positive().doc("time step"))
      .add(ParamSpec::quantity("diameter", Dimension::lengthDim()).defaultValue("2 mm").positive().doc("d"))
      .add(ParamSpec::integer("steps").defaultValue(10).min(1).doc("n"))
      .add(ParamSpec::string("law").defaultValue("linear").options({"linear", "hertz"}).doc("contact law"))
      .add(ParamSpec::quantityList("gravity", Dimension::acceleration(), 3)
               .defaultValue(json::array({0, 0, -9.81}))
               .doc("g"))
      .add(ParamSpec::boolean("progress").defaultValue(true).doesNotAffectResults().doc("progress output"));
  return s;
}
}  // namespace

TEST(ParamSchema, ResolvesToSIAndFillsDefaults) {
  Diagnostics d;
  const json r = schema().resolve(json{{"dt", "0.1 ms"}, {"law", "hertz"}}, {}, UnitSystem::si(), "/p", d);
  ASSERT_TRUE(d.empty()) << d.format("t");
  EXPECT_DOUBLE_EQ(r["dt"].get<double>(), 1e-4);
  EXPECT_DOUBLE_EQ(r["diameter"].get<double>(), 2e-3);
  EXPECT_EQ(r["steps"].get<int>(), 10);
  EXPECT_EQ(r["law"], "hertz");
  EXPECT_DOUBLE_EQ(r["gravity"][2].get<double>(), -9.81);
}

TEST(ParamSchema, DefaultsAreSIEvenUnderReducedUnits) {
  Diagnostics d;
  const auto reduced = UnitSystem::reduced(0.004, 1e-4, 9.81);
  const json r = schema().resolve(json{{"dt", 2e-4}}, {}, reduced, "/p", d);
  ASSERT_TRUE(d.empty());
  EXPECT_DOUBLE_EQ(r["diameter"].get<double>(), 2e-3);           // default: SI, not 2 mm * d0
  EXPECT_DOUBLE_EQ(r["dt"].get<double>(), 2e-4 * reduced.t0());  // bare number: reduced
}

TEST(ParamSchema, ReportsEveryProblemWithPointer) {
  Diagnostics d;
  schema().resolve(json{{"dt", -1}, {"stepz", 3}, {"law", "herz"}, {"gravity", {0, 0}}}, {}, UnitSystem::si(),
                   "/stages/s/params", d);
  ASSERT_EQ(d.size(), 4u) << d.format("t");
  const std::string all = d.format("cfg");
  EXPECT_NE(all.find("/stages/s/params/dt: expected dt > 0 (SI, s), found -1"), std::string::npos) << all;
  EXPECT_NE(all.find("/stages/s/params/stepz: unknown parameter \"stepz\" (did you mean \"steps\"?)"),
            std::string::npos)
      << all;
  EXPECT_NE(
      all.find("/stages/s/params/law: expected string: one of linear|hertz, found \"herz\" (did you mean \"hertz\"?)"),
      std::string::npos)
      << all;
  EXPECT_NE(all.find("/stages/s/params/gravity: expected a list of 3 quantities"), std::string::npos) << all;
}

TEST(ParamSchema, MissingRequiredUnlessSwept) {
  Diagnostics d;
  schema().resolve(json::object(), {}, UnitSystem::si(), "/p", d);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_NE(d.items()[0].message.find("missing required parameter \"dt\""), std::string::npos);
  Diagnostics d2;
  schema().resolve(json::object(), {"dt"}, UnitSystem::si(), "/p", d2);
  EXPECT_TRUE(d2.empty());
}

TEST(ParamSchema, KeyParamsDropWhatDoesNotAffectResults) {
  Diagnostics d;
  const json r = schema().resolve(json{{"dt", 1e-4}, {"progress", false}}, {}, UnitSystem::si(), "/p", d);
  const json k = schema().keyParams(r);
  EXPECT_TRUE(r.contains("progress"));
  EXPECT_FALSE(k.contains("progress"));
  EXPECT_TRUE(k.contains("dt"));
}

TEST(ParamSchema, IntegerAcceptsIntegralFloatOnly) {
  Diagnostics d;
  const json r = schema().resolve(json{{"dt", 1e-4}, {"steps", 3.0}}, {}, UnitSystem::si(), "/p", d);
  EXPECT_TRUE(d.empty());
  EXPECT_TRUE(r["steps"].is_number_integer());
  Diagnostics d2;
  schema().resolve(json{{"dt", 1e-4}, {"steps", 3.5}}, {}, UnitSystem::si(), "/p", d2);
  EXPECT_EQ(d2.size(), 1u);
}

namespace {
ParamSchema listSchema() {
  ParamSchema s;
  s.add(ParamSpec::integerList("ids", 0).defaultValue(json::array()).min(0).doc("particle ids"))
      .add(ParamSpec::integerList("cells", 3).min(1).max(1000).doc("cells per axis"));
  return s;
}
}  // namespace

TEST(ParamSchema, IntegerListNamesTheElement) {
  Diagnostics d;
  listSchema().resolve(json{{"ids", {3, 1.5, -1}}, {"cells", {2, 2, 2000}}}, {}, UnitSystem::si(), "/stages/x/params",
                       d);
  const std::string all = d.format("cfg");
  ASSERT_EQ(d.size(), 3u) << all;
  EXPECT_NE(all.find("/stages/x/params/ids/1: expected an integer, found number 1.5"), std::string::npos) << all;
  EXPECT_NE(all.find("/stages/x/params/ids/2: expected ids >= 0, found -1"), std::string::npos) << all;
  EXPECT_NE(all.find("/stages/x/params/cells/2: expected cells in [1, 1000], found 2000"), std::string::npos) << all;
}

TEST(ParamSchema, IntegerListHasItsLength) {
  Diagnostics d;
  listSchema().resolve(json{{"cells", {2, 2}}}, {}, UnitSystem::si(), "/p", d);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_NE(d.items()[0].message.find("expected a list of 3 integers"), std::string::npos) << d.format("t");
  Diagnostics d2;
  listSchema().resolve(json{{"cells", "2 2 2"}}, {}, UnitSystem::si(), "/p", d2);
  EXPECT_EQ(d2.size(), 1u);
}

// The resolved text enters the stage key: integer lists keep the text the number lists they
// replace had (3.0, not 3), so existing configs keep their keys.
TEST(ParamSchema, IntegerListResolvesToTheTextOfANumberList) {
  Diagnostics d;
  const json r = listSchema().resolve(json{{"ids", {0, 7.0}}, {"cells", {4, 5, 6}}}, {}, UnitSystem::si(), "/p", d);
  ASSERT_TRUE(d.empty()) << d.format("t");
  EXPECT_EQ(r["ids"].dump(), "[0.0,7.0]");
  EXPECT_EQ(r["cells"].dump(), "[4.0,5.0,6.0]");
  EXPECT_EQ(r["cells"][1].get<std::int64_t>(), 5);
  ParamSchema numbers;
  numbers.add(ParamSpec::quantityList("ids", Dimension::none(), 0).doc("as declared before"));
  EXPECT_EQ(numbers.resolve(json{{"ids", {0, 7}}}, {}, UnitSystem::si(), "/p", d)["ids"].dump(), r["ids"].dump());
  EXPECT_EQ(listSchema().find("ids")->typeDescription(), "list of any number of integers");
  EXPECT_EQ(listSchema().find("cells")->typeDescription(), "list of 3 integers");
}

namespace {
std::shared_ptr<ParamSchema> contactRules() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::number("gamma_n").doc("damping"))
      .add(ParamSpec::number("restitution").doc("restitution"))
      .exactlyOneOf({"gamma_n", "restitution"});
  return s;
}

ParamSchema ruleSchema() {
  ParamSchema s;
  s.add(ParamSpec::string("lammps_data").doc("file"))
      .add(ParamSpec::string("initial_frame").doc("file"))
      .add(ParamSpec::string("lammps_types").doc("types"))
      .add(ParamSpec::string("a").doc("a"))
      .add(ParamSpec::string("b").doc("b"))
      .add(ParamSpec::object("contact", contactRules()).doc("contact"))
      .add(ParamSpec::objectList("walls", contactRules()).doc("walls"))
      .atMostOneOf({"lammps_data", "initial_frame"}, "the initial state")
      .requiresKey("lammps_types", "lammps_data")
      .goTogether({"a", "b"});
  return s;
}

std::string checkRules(const json& params) {
  Diagnostics d;
  const ParamSchema s = ruleSchema();
  const json resolved = s.resolve(params, {}, UnitSystem::si(), "/stages/x/params", d);
  EXPECT_TRUE(d.empty()) << d.format("resolve");
  s.checkRules(resolved, "/stages/x/params", d);
  return d.empty() ? "" : d.format("cfg");
}
}  // namespace

TEST(ParamSchema, KeyRulesPassWhenKept) {
  EXPECT_EQ(checkRules(json{{"contact", {{"gamma_n", 1}}}}), "");
  EXPECT_EQ(checkRules(json{{"contact", {{"restitution", 0.9}}},
                            {"lammps_data", "f"},
                            {"lammps_types", "t"},
                            {"a", "1"},
                            {"b", "2"},
                            {"walls", {{{"gamma_n", 1}}, {{"restitution", 0.5}}}}}),
            "");
}

TEST(ParamSchema, ExactlyOneOfAtTheObjectAndInEachListElement) {
  const std::string both = checkRules(json{{"contact", {{"gamma_n", 1}, {"restitution", 0.9}}}});
  EXPECT_NE(both.find("/stages/x/params/contact: give exactly one of gamma_n and restitution, found both"),
            std::string::npos)
      << both;
  const std::string neither =
      checkRules(json{{"contact", {{"gamma_n", 1}}}, {"walls", {{{"gamma_n", 1}}, json::object()}}});
  EXPECT_NE(neither.find("/stages/x/params/walls/1: give exactly one of gamma_n and restitution, found neither"),
            std::string::npos)
      << neither;
  EXPECT_EQ(neither.find("/walls/0"), std::string::npos) << neither;
}

TEST(ParamSchema, AtMostOneRequiresAndGoTogether) {
  const std::string all =
      checkRules(json{{"contact", {{"gamma_n", 1}}}, {"lammps_data", "f"}, {"initial_frame", "g"}, {"a", "1"}});
  EXPECT_NE(
      all.find("/stages/x/params: give at most one of lammps_data and initial_frame (the initial state), found both"),
      std::string::npos)
      << all;
  EXPECT_NE(all.find("/stages/x/params/b: a and b go together: a given without b"), std::string::npos) << all;
  const std::string needs = checkRules(json{{"contact", {{"gamma_n", 1}}}, {"lammps_types", "t"}});
  EXPECT_NE(needs.find("/stages/x/params/lammps_types: lammps_types requires lammps_data, which is not given"),
            std::string::npos)
      << needs;
  // One direction only: lammps_data alone is fine.
  EXPECT_EQ(checkRules(json{{"contact", {{"gamma_n", 1}}}, {"lammps_data", "f"}}), "");
}

TEST(ParamSchema, KeyRulesDescribeThemselves) {
  const ParamSchema s = ruleSchema();
  ASSERT_EQ(s.rules().size(), 3u);
  EXPECT_EQ(s.rules()[0].description(), "at most one of lammps_data and initial_frame (the initial state)");
  EXPECT_EQ(s.rules()[1].description(), "lammps_types requires lammps_data");
  EXPECT_EQ(s.rules()[2].description(), "a and b go together");
  EXPECT_EQ(s.find("walls")->nested()->rules()[0].description("walls[]."),
            "exactly one of walls[].gamma_n and walls[].restitution");
}
