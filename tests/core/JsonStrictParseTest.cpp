#include <gtest/gtest.h>

#include "core/json/StrictParse.hpp"

using grainbridge::core::json::closestMatch;
using grainbridge::core::json::Diagnostics;
using grainbridge::core::json::parseStrict;

TEST(StrictParse, AcceptsValidJsonAndKeepsEveryValue) {
  Diagnostics d;
  auto doc = parseStrict(R"({"a": [1, 2.5, {"b": "x"}], "c": null, "d": true})", d);
  ASSERT_TRUE(doc.has_value()) << d.format("test");
  EXPECT_EQ((*doc)["a"][1].get<double>(), 2.5);
  EXPECT_EQ((*doc)["a"][2]["b"], "x");
  EXPECT_TRUE((*doc)["c"].is_null());
  EXPECT_TRUE(d.empty());
}

TEST(StrictParse, RejectsRepeatedKeyWithItsPointer) {
  Diagnostics d;
  auto doc = parseStrict(R"({"stages": {"bed": {"type": "x"}, "bed": {"type": "y"}}})", d);
  EXPECT_FALSE(doc.has_value());
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d.items()[0].where, "/stages/bed");
  EXPECT_NE(d.items()[0].message.find("more than once"), std::string::npos);
}

TEST(StrictParse, RepeatedKeyInsideArrayElementHasIndexInPointer) {
  Diagnostics d;
  auto doc = parseStrict(R"({"list": [{"a": 1}, {"a": 1, "a": 2}]})", d);
  EXPECT_FALSE(doc.has_value());
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d.items()[0].where, "/list/1/a");
}

TEST(StrictParse, SyntaxErrorNamesLineAndColumn) {
  Diagnostics d;
  auto doc = parseStrict("{\n  \"a\": 1,\n  \"b\": ,\n}", d);
  EXPECT_FALSE(doc.has_value());
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d.items()[0].where, "line 3, column 8");
}

TEST(StrictParse, KeysWithSlashAreEscapedInPointer) {
  Diagnostics d;
  parseStrict(R"({"a/b": {"x": 1, "x": 2}})", d);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d.items()[0].where, "/a~1b/x");
}

TEST(ClosestMatch, SuggestsPlausibleTypoOnly) {
  EXPECT_EQ(closestMatch("n_partcles", {"n_particles", "diameter"}), "n_particles");
  EXPECT_EQ(closestMatch("zzzzzz", {"n_particles", "diameter"}), "");
}
