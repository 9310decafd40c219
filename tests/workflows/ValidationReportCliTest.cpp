// `grainbridge report validation`: physics-test records become one page with reference,
// ours, deviation and status; a failed figure makes the command exit 1; no sources is a usage
// error.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/Cli.hpp"

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
