// Statistics over realisations (issue 55, workflows/report/Realisations): the grouping of runs
// into arms by their sweep points, and the mean, sample standard deviation, standard error and the
// difference of two arms' means on numbers worked by hand.
#include "workflows/report/Realisations.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace grainbridge::workflows::report;
using nlohmann::json;

TEST(Realisations, MeanSampleStandardDeviationAndStandardErrorOfKnownValues) {
  // 1, 2, 3, 4: mean 2.5, squares about it 2.25 + 0.25 + 0.25 + 2.25 = 5, sd sqrt(5 / 3), se sd / 2.
  const auto s = overRealisations({1.0, 2.0, 3.0, 4.0});
  EXPECT_EQ(s.n, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.sd, std::sqrt(5.0 / 3.0));
  EXPECT_DOUBLE_EQ(s.se, std::sqrt(5.0 / 3.0) / 2.0);
}

TEST(Realisations, OneRealisationHasAMeanButNoSpreadAndAMissingValueNoMean) {
  const auto one = overRealisations({0.7});
  EXPECT_EQ(one.n, 1u);
  EXPECT_DOUBLE_EQ(one.mean, 0.7);
  EXPECT_TRUE(std::isnan(one.sd));
  EXPECT_TRUE(std::isnan(one.se));
  const auto missing = overRealisations({0.7, NAN});
  EXPECT_EQ(missing.n, 2u);
  EXPECT_TRUE(std::isnan(missing.mean));
  EXPECT_TRUE(std::isnan(missing.se));
}

TEST(Realisations, TheDifferenceOfTwoMeansCarriesBothStandardErrors) {
  // 1..4: se^2 = 5/12; 2, 4, 6: mean 4, sd 2, se^2 = 4/3; the difference 1.5 ± sqrt(5/12 + 4/3).
  const auto d = meanDifference(overRealisations({1.0, 2.0, 3.0, 4.0}), overRealisations({2.0, 4.0, 6.0}));
  EXPECT_DOUBLE_EQ(d.value, 1.5);
  EXPECT_NEAR(d.se, std::sqrt(5.0 / 12.0 + 4.0 / 3.0), 1e-15);
  EXPECT_NEAR(d.standardErrors(), 1.5 / std::sqrt(1.75), 1e-14);
}

TEST(Realisations, RunsDifferingOnlyInTheSeedFormOneArmAndInAnotherParameterTwo) {
  const std::vector<SweptRun> runs = {{"bed", {{"rotation_model", true}, {"seed", 10}}},
                                      {"bed", {{"rotation_model", false}, {"seed", 2}}},
                                      {"bed", {{"rotation_model", true}, {"seed", 2}}},
                                      {"bed", {{"rotation_model", false}, {"seed", 10}}},
                                      {"bed", {{"rotation_model", true}, {"seed", 3}}}};
  const auto arms = groupArms(runs, "seed");
  ASSERT_EQ(arms.size(), 2u);
  EXPECT_EQ(arms[0].label, "bed (rotation_model false)");
  EXPECT_EQ(arms[0].runs, (std::vector<std::size_t>{1, 3}));
  EXPECT_EQ(arms[0].realisations, (std::vector<std::string>{"2", "10"}));  // by value, not as text
  EXPECT_EQ(arms[1].label, "bed (rotation_model true)");
  EXPECT_EQ(arms[1].runs, (std::vector<std::size_t>{2, 4, 0}));
  EXPECT_EQ(arms[1].written, (json{{"rotation_model", true}}));
  // They differ in rotation_model alone: one contrast, from the first arm to the second.
  const auto contrasts = armContrasts(arms);
  ASSERT_EQ(contrasts.size(), 1u);
  EXPECT_EQ(contrasts[0].from, 0u);
  EXPECT_EQ(contrasts[0].to, 1u);
  EXPECT_EQ(contrasts[0].parameter, "rotation_model");
}

TEST(Realisations, ARunNotSweptOverTheSeedIsAnArmOfOneAndStagesNeverMerge) {
  const std::vector<SweptRun> runs = {{"mono", json::object()},
                                      {"bed", {{"seed", 1}}},
                                      {"bed", {{"seed", 2}}},
                                      {"other", {{"seed", 1}}},
                                      {"other", {{"seed", 2}}}};
  const auto arms = groupArms(runs, "seed");
  ASSERT_EQ(arms.size(), 3u);
  EXPECT_EQ(arms[0].label, "bed");
  EXPECT_EQ(arms[0].runs.size(), 2u);
  EXPECT_EQ(arms[1].label, "mono");
  EXPECT_EQ(arms[1].runs, (std::vector<std::size_t>{0}));
  EXPECT_TRUE(arms[1].realisations.empty());
  EXPECT_EQ(arms[2].label, "other");
  EXPECT_EQ(arms[2].runs, (std::vector<std::size_t>{3, 4}));
  // Two stages are two settings, but not a contrast of one parameter: none drawn between them.
  EXPECT_TRUE(armContrasts(arms).empty());
}

TEST(Realisations, NoContrastBetweenArmsDifferingInTwoParametersOrOfOneRealisation) {
  const std::vector<SweptRun> runs = {{"bed", {{"a", 1}, {"b", 1}, {"seed", 1}}},
                                      {"bed", {{"a", 1}, {"b", 1}, {"seed", 2}}},
                                      {"bed", {{"a", 2}, {"b", 2}, {"seed", 1}}},
                                      {"bed", {{"a", 2}, {"b", 2}, {"seed", 2}}},
                                      {"bed", {{"a", 1}, {"b", 2}, {"seed", 1}}}};
  const auto arms = groupArms(runs, "seed");
  ASSERT_EQ(arms.size(), 3u);
  // (a 1, b 2) differs from each of the others in one parameter, but has one realisation.
  EXPECT_TRUE(armContrasts(arms).empty());
}
