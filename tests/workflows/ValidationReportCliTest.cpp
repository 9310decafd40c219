// `grainbridge report validation`: physics-test records become one page with reference,
// ours, deviation and status; a failed figure makes the command exit 1; no sources is a usage
// error.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/Cli.hpp"
#include "tests/support/TinyShear.hpp"

using namespace grainbridge::testing;
using ::testing::HasSubstr;

namespace {

void writeRecord(const std::filesystem::path& dir, const std::string& id, double reference, double ours, bool passed) {
  std::filesystem::create_directories(dir);
  const nlohmann::json record = {{"id", id},
                                 {"section", "DEM (Chapter 6)"},
                                 {"check", "check " + id},
                                 {"reference", "Eq. 6.9"},
                                 {"reference_value", reference},
                                 {"ours", ours},
                                 {"tolerance", "1 %"},
                                 {"passed", passed},
                                 {"note", ""}};
  writeText(dir / (id + ".json"), record.dump());
}

}  // namespace

TEST(ValidationReportCli, GathersRecordsIntoOnePageWithDeviations) {
  TempDir work;
  writeRecord(work.path() / "records", "dem.a", 0.9054, 0.9050, true);
  writeRecord(work.path() / "records", "dem.b", 2.0, 2.5, true);
  const auto r = runGrainbridge(work.path(), "report validation --records records -o out/v.html");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("2 figures, 2 pass, 0 fail, 0 reported"));
  const std::string html = readText(work.path() / "out/v.html");
  EXPECT_THAT(html, HasSubstr("check dem.a"));
  EXPECT_THAT(html, HasSubstr("+25.00 %"));  // (2.5 - 2) / 2
  EXPECT_THAT(readText(work.path() / "out/v.csv"), HasSubstr("dem.b,check dem.b,Eq. 6.9,2,2.5,+25.00 %,1 %,pass"));
}

TEST(ValidationReportCli, AFailedFigureMakesTheCommandFail) {
  TempDir work;
  writeRecord(work.path() / "records", "dem.a", 1.0, 1.2, false);
  const auto r = runGrainbridge(work.path(), "report validation --records records -o v.html");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_THAT(r.output, HasSubstr("1 figures, 0 pass, 1 fail"));
}

TEST(ValidationReportCli, NoSourcesIsAUsageError) {
  TempDir work;
  const auto r = runGrainbridge(work.path(), "report validation --records nowhere");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.output, HasSubstr("no validation records in 'nowhere'"));
}

// A compare stage run again (here: a new title) supersedes its older run: the report lists each
// state's figures once, from the newest run.
TEST(ValidationReportCli, OnlyTheNewestRunOfACompareStageIsListed) {
  TempDir work;
  nlohmann::json wf = {
      {"name", "kt"},
      {"stages",
       {{"shear", {{"type", "dem"}, {"params", tinyShearDemParams()}}},
        {"closure", {{"type", "extract"}, {"from", "shear"}, {"params", {{"family", "simple_shear"}}}}},
        {"kt", {{"type", "compare"}, {"from", "closure"}, {"params", {{"title", "first"}}}}}}}};
  writeText(work.path() / "wf.json", wf.dump());
  ASSERT_EQ(runGrainbridge(work.path(), "run wf.json -q").exitCode, 0);
  wf["stages"]["kt"]["params"]["title"] = "second";
  writeText(work.path() / "wf.json", wf.dump());
  ASSERT_EQ(runGrainbridge(work.path(), "run wf.json -q").exitCode, 0);

  // One state, three asserted figures (p*, tau*, T*): whether this tiny run passes 15 % or not
  // does not matter here, only that each figure is listed once, from run 4 (the second compare).
  const auto r = runGrainbridge(work.path(), "report validation --db results/kt/grainbridge.sqlite -o v.html");
  EXPECT_THAT(r.output, HasSubstr("3 figures")) << r.output;
  const std::string csv = readText(work.path() / "v.csv");
  EXPECT_THAT(csv, HasSubstr("(workflow kt, run 4)"));
  EXPECT_THAT(csv, ::testing::Not(HasSubstr("(workflow kt, run 3)")));
}
