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
