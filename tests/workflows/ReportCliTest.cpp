// `grainbridge report` as a user meets it (issue 16): the page's path on the first line, the
// sweep as the config wrote it in the logs, and --open handing the page to the system browser.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/Cli.hpp"

namespace fs = std::filesystem;
using namespace grainbridge::testing;

namespace {

const char* kWorkflow = R"({
  "name": "rw",
  "stages": {
    "gas": {"type": "particle_gas",
            "params": {"n_particles": 50, "solid_fraction": 0.1, "seed": 2, "progress": false},
            "sweep": {"diameter": ["1.3 mm", "2 mm"]}},
    "rep": {"type": "report", "from": "gas"}
  }
})";

}  // namespace

TEST(ReportCli, PrintsThePageFirstAndLabelsTheSweepAsWritten) {
  TempDir work;
  writeText(work.path() / "rw.json", kWorkflow);
  const auto run = runGrainbridge(work.path(), "run rw.json");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("gas[diameter=1.3 mm]"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("0.0013000000000000002"), std::string::npos) << run.output;

  const auto report = runGrainbridge(work.path(), "report rw.json");
  ASSERT_EQ(report.exitCode, 0) << report.output;
  const std::string first = report.output.substr(0, report.output.find('\n'));
  EXPECT_TRUE(first.ends_with("results/rw/report/report.html")) << report.output;
  ASSERT_TRUE(fs::exists(first));
  const std::string page = readText(first);
  EXPECT_NE(page.find("1.3 mm"), std::string::npos);
  EXPECT_NE(page.find("rw/grainbridge.sqlite"), std::string::npos);
}

TEST(ReportCli, OpenHandsThePageToTheBrowser) {
  TempDir work;
  writeText(work.path() / "rw.json", kWorkflow);
  ASSERT_EQ(runGrainbridge(work.path(), "run rw.json").exitCode, 0);
  // A stand-in browser that records what it was asked to open. It writes a temporary file and
  // renames it, so "opened" appears whole: the shell's `>` creates the file before echo fills it,
  // and the poll below could read it empty.
  const fs::path browser = work.path() / "browser.sh";
  const std::string opened_path = (work.path() / "opened").string();
  writeText(browser, "#!/bin/sh\necho \"$1\" > '" + opened_path + ".tmp' && mv '" + opened_path + ".tmp' '" +
                         opened_path + "'\n");
  fs::permissions(browser, fs::perms::owner_all);
  const auto report = runGrainbridge(work.path(), "report rw.json --open", "BROWSER='" + browser.string() + "'");
  ASSERT_EQ(report.exitCode, 0) << report.output;
  const fs::path opened = work.path() / "opened";
  for (int i = 0; i < 100 && !fs::exists(opened); ++i) ::usleep(20000);  // the browser runs in the background
  ASSERT_TRUE(fs::exists(opened)) << report.output;
  EXPECT_NE(readText(opened).find("results/rw/report/report.html"), std::string::npos);
}

TEST(ReportCli, OpenWithoutABrowserSaysWhereThePageIs) {
  TempDir work;
  writeText(work.path() / "rw.json", kWorkflow);
  ASSERT_EQ(runGrainbridge(work.path(), "run rw.json").exitCode, 0);
  // A PATH with gnuplot (the page's plots) and no browser.
  const fs::path bin = work.path() / "bin";
  fs::create_directories(bin);
  const auto gnuplot = runCommand("command -v gnuplot");
  ASSERT_EQ(gnuplot.exitCode, 0);
  fs::create_symlink(gnuplot.output.substr(0, gnuplot.output.find('\n')), bin / "gnuplot");
  const auto report = runGrainbridge(work.path(), "report rw.json --open", "BROWSER= PATH='" + bin.string() + "'");
  EXPECT_EQ(report.exitCode, 0) << report.output;
  EXPECT_NE(report.output.find("no browser found"), std::string::npos) << report.output;
}
