// bed_compare over realisations (issue 55): arms.csv, the findings' sentences and the mean-and-
// band figure from hand-made runs (workflows/report/BedArms, BedFigures), no stage run.
#include "workflows/report/BedArms.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "workflows/report/BedFigures.hpp"

using namespace grainbridge::workflows::report;
using nlohmann::json;

namespace {

// A binary bed at one seed: its window means and a three-sample s_p series.
BedRun run(const std::string& label, double height, double sp, std::vector<double> time = {0.0, 0.1, 0.2}) {
  BedRun r;
  r.label = label;
  r.meanHeight = height;
  r.values["segregation_percentage"] = sp;
  r.series["segregation_percentage"] = {0.0, sp / 2, sp};
  r.series["time"] = std::move(time);
  return r;
}

struct Fixture {
  std::vector<BedRun> runs = {run("bed (rotation_model false, seed 1)", 0.10, 50.0),
                              run("bed (rotation_model false, seed 2)", 0.12, 54.0),
                              run("bed (rotation_model true, seed 1)", 0.12, 64.0),
                              run("bed (rotation_model true, seed 2)", 0.14, 70.0), run("mono", 0.09, NAN)};
  std::vector<Arm> arms = groupArms({{"bed", {{"rotation_model", false}, {"seed", 1}}},
                                     {"bed", {{"rotation_model", false}, {"seed", 2}}},
                                     {"bed", {{"rotation_model", true}, {"seed", 1}}},
                                     {"bed", {{"rotation_model", true}, {"seed", 2}}},
                                     {"mono", json::object()}},
                                    "seed");
};

}  // namespace

TEST(BedArms, ArmsCsvHasARowPerArmWithItsRealisationsAndEmptyFieldsWhereThereIsNoSpread) {
  const Fixture f;
  const std::string csv = armsCsv(bedArms(f.runs, f.arms));
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line,
            "arm,realisations,realisation_values,mean_height_mean,mean_height_sd,mean_height_se,"
            "segregation_percentage_mean,segregation_percentage_sd,segregation_percentage_se");
  // 0.10 and 0.12: mean 0.11, sd 0.02 / sqrt(2), se 0.01; s_p 50 and 54 %: se 2.
  std::getline(lines, line);
  EXPECT_EQ(line.rfind("bed (rotation_model false),2,1;2,0.11,", 0), 0u) << line;
  const auto arms = bedArms(f.runs, f.arms);
  EXPECT_NEAR(arms[0].outputs.at("mean_height").se, 0.01, 1e-15);
  EXPECT_NEAR(arms[0].outputs.at("segregation_percentage").se, 2.0, 1e-13);
  std::getline(lines, line);
  EXPECT_EQ(line.rfind("bed (rotation_model true),2,1;2,", 0), 0u) << line;
  // The run without a seed: its height as the mean, no spread, no s_p recorded.
  std::getline(lines, line);
  EXPECT_EQ(line, "mono,1,,0.09,,,,,");
  EXPECT_FALSE(std::getline(lines, line));
}

TEST(BedArms, TheHeadlineGivesEachArmsMeansAndTheDifferenceOneSettingMakesInStandardErrors) {
  const Fixture f;
  const std::string headline = armsHeadline(bedArms(f.runs, f.arms), "seed");
  EXPECT_NE(headline.find("bed (rotation_model false): s_p 52.0 ± 2.0 %, mean height 0.110 ± 0.010 m (mean and "
                          "standard error over 2 realisations: seed 1, 2)"),
            std::string::npos)
      << headline;
  // s_p: 67 - 52 = 15 ± sqrt(2^2 + 3^2) = 3.6 percentage points, 4.2 standard errors; the height
  // 0.13 - 0.11 = 0.02 ± sqrt(2) 0.01, 1.4 standard errors.
  EXPECT_NE(headline.find("bed: rotation_model false → true raises s_p by 15.0 ± 3.6 percentage points (4.2 standard "
                          "errors), raises mean height by 0.020 ± 0.014 m (1.4 standard errors); 2 realisations each."),
            std::string::npos)
      << headline;
  // An arm of one has no sentence.
  EXPECT_EQ(headline.find("mono"), std::string::npos) << headline;
  EXPECT_EQ(armsHeadline(bedArms({f.runs[4]}, groupArms({{"mono", json::object()}}, "seed")), "seed"), "");
}

TEST(BedArms, TheRealisationsFigureDrawsEachArmsMeanWithABandOfOneStandardError) {
  const Fixture f;
  const Figure figure = realisationsFigure(f.runs, f.arms, "segregation_percentage", "s_p", {"s_p", "–"});
  ASSERT_EQ(figure.series.size(), 4u);  // a band and a line per arm of two; none for the run alone
  const Series& band = figure.series[0];
  const Series& line = figure.series[1];
  EXPECT_EQ(band.style, Series::Style::Band);
  EXPECT_EQ(line.style, Series::Style::Line);
  EXPECT_EQ(line.model, "bed (rotation_model false)");
  EXPECT_EQ(band.model, line.model);
  EXPECT_NE(figure.series[2].model, line.model);
  // A colour per arm, its band in its line's.
  EXPECT_FALSE(line.colour.empty());
  EXPECT_EQ(band.colour, line.colour);
  EXPECT_NE(figure.series[3].colour, line.colour);
  EXPECT_EQ(line.x, (std::vector<double>{0.0, 0.1, 0.2}));
  EXPECT_NEAR(line.y[2], 52.0, 1e-13);
  EXPECT_NEAR(band.yError[2], 2.0, 1e-13);
  EXPECT_NEAR(band.yError[1], 1.0, 1e-13);
}

TEST(BedArms, TheRealisationsFigureUsesTheCommonTimesAndRefusesRunsThatShareTooFew) {
  Fixture f;
  // A realisation run on to 0.3 s: the mean is over the times both have.
  f.runs[1] = run("bed (rotation_model false, seed 2)", 0.12, 0.54, {0.0, 0.1, 0.2, 0.3});
  f.runs[1].series["segregation_percentage"].push_back(0.6);
  const Figure figure = realisationsFigure(f.runs, f.arms, "segregation_percentage", "s_p", {"s_p", "–"});
  EXPECT_EQ(figure.series[1].x, (std::vector<double>{0.0, 0.1, 0.2}));
  // Sampled at other times altogether: refused, naming the runs.
  f.runs[1] = run("bed (rotation_model false, seed 2)", 0.12, 0.54, {0.05, 0.15, 0.25});
  try {
    (void)realisationsFigure(f.runs, f.arms, "segregation_percentage", "s_p", {"s_p", "–"});
    FAIL() << "times shared by no sample were not refused";
  } catch (const grainbridge::Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bed (rotation_model false, seed 1), bed (rotation_model false, seed 2)"), std::string::npos)
        << what;
    EXPECT_NE(what.find("output_interval"), std::string::npos) << what;
  }
}
