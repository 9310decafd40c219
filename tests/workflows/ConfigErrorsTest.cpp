// Every bad config in bad_configs/ must make `grainbridge check` exit 2 before any work, and
// print every line of its .expect file (the JSON pointer or line/column, what was expected and
// what was found). One data file per case, one generic driver (STYLE.md 10).
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "tests/support/Cli.hpp"

namespace fs = std::filesystem;
using namespace grainbridge::testing;

namespace {

std::vector<std::string> badConfigCases() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(sourceDir() / "tests/workflows/bad_configs")) {
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class BadConfig : public ::testing::TestWithParam<std::string> {};

TEST_P(BadConfig, ExitsTwoAndNamesEveryProblem) {
  const fs::path dir = sourceDir() / "tests/workflows/bad_configs";
  TempDir work;
  const auto r = runGrainbridge(work.path(), "check '" + (dir / (GetParam() + ".json")).string() + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  std::istringstream expected(readText(dir / (GetParam() + ".expect")));
  std::string line;
  int lines = 0;
  while (std::getline(expected, line)) {
    if (line.empty()) continue;
    ++lines;
    EXPECT_NE(r.output.find(line), std::string::npos) << "missing: " << line << "\noutput:\n" << r.output;
  }
  EXPECT_GT(lines, 0) << "case without expectations";
  // Nothing was started: no results folder, no database.
  EXPECT_FALSE(fs::exists(work.path() / "results"));
}

INSTANTIATE_TEST_SUITE_P(AllCases, BadConfig, ::testing::ValuesIn(badConfigCases()),
                         [](const auto& p) { return p.param; });

TEST(BadConfigFile, MissingFileIsAConfigError) {
  TempDir work;
  const auto r = runGrainbridge(work.path(), "check does-not-exist.json");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("does-not-exist.json: (document root): config file does not exist"), std::string::npos)
      << r.output;
}

TEST(BadConfigFile, DirectoryIsAConfigError) {
  TempDir work;
  fs::create_directories(work.path() / "cfg.json");
  const auto r = runGrainbridge(work.path(), "check cfg.json");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("cfg.json: (document root): is a directory"), std::string::npos) << r.output;
}

TEST(BadConfigFile, RunRefusesBadConfigBeforeAnyWork) {
  TempDir work;
  writeText(work.path() / "cfg.json", readText(sourceDir() / "tests/workflows/bad_configs/many_errors.json"));
  const auto r = runGrainbridge(work.path(), "run cfg.json");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_FALSE(fs::exists(work.path() / "results"));
}

// A request the upstream run cannot serve is refused before the upstream stage starts: no dem
// instance runs, none is recorded.
TEST(BadConfigFile, RunRefusesAnExtractRequestBeforeTheDemRuns) {
  TempDir work;
  writeText(work.path() / "cfg.json",
            readText(sourceDir() / "tests/workflows/bad_configs/extract_window_after_run.json"));
  const auto r = runGrainbridge(work.path(), "run cfg.json");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("/stages/avg/params/start_time: the averaging window starts after the last frame"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(work.path() / "results")) << "a stage started (or a database was made)";
}

// The upstream dem of this case is swept over three seeds; the window misses all three runs in
// the same way, so the problem is reported once.
TEST(BadConfigFile, AProblemWithEveryUpstreamPointIsReportedOnce) {
  TempDir work;
  const auto r = runGrainbridge(
      work.path(),
      "check '" + (sourceDir() / "tests/workflows/bad_configs/extract_window_after_run.json").string() + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  const std::string message = "the averaging window starts after the last frame";
  const auto first = r.output.find(message);
  ASSERT_NE(first, std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(message, first + 1), std::string::npos) << r.output;
}

TEST(Cli, UsageErrorExitsTwo) {
  TempDir work;
  EXPECT_EQ(runGrainbridge(work.path(), "frobnicate").exitCode, 2);
  EXPECT_EQ(runGrainbridge(work.path(), "run").exitCode, 2);
  EXPECT_EQ(runGrainbridge(work.path(), "run --help").exitCode, 0);
}

}  // namespace

namespace {
// docs/stages.md is generated from the parameter declarations; it must not drift from them.
TEST(StagesReference, DocsMatchTheDeclarations) {
  TempDir work;
  const auto r = runCommand(grainbridgeBinary() + " stages --markdown");
  ASSERT_EQ(r.exitCode, 0);
  const std::string doc = readText(sourceDir() / "docs/stages.md");
  EXPECT_NE(doc.find(r.output), std::string::npos)
      << "docs/stages.md is out of date: regenerate its table part with `grainbridge stages --markdown`";
  // Each parameter row has its six cells on GitHub: a `|` inside a cell is escaped.
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| `", 0) != 0) continue;
    int bars = 0;
    for (std::size_t i = 0; i < line.size(); ++i) bars += line[i] == '|' && (i == 0 || line[i - 1] != '\\');
    EXPECT_EQ(bars, 7) << line;
  }
}

TEST(StagesReference, OneTypeByName) {
  auto r = runCommand(grainbridgeBinary() + " stages mfm");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.rfind("mfm (impl_version", 0), 0u) << r.output;
  EXPECT_EQ(r.output.find("dem (impl_version"), std::string::npos);
  r = runCommand(grainbridgeBinary() + " stages mfn");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("no stage type \"mfn\" (did you mean \"mfm\"?)"), std::string::npos) << r.output;
}
}  // namespace
