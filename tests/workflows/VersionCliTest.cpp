// `grainbridge --version` (issue 16, item 5): the version, git SHA and dirty flag, and the
// versions of HDF5, SQLite, Eigen and MPI the binary was built with; exit 0 without a
// subcommand (it used to exit 2 with "A subcommand is required").
#include <gtest/gtest.h>

#include <regex>

#include "core/Version.hpp"
#include "tests/support/Cli.hpp"

using namespace grainbridge::testing;

TEST(VersionCli, NamesTheCodeAndEveryLibrary) {
  TempDir work;
  const auto r = runGrainbridge(work.path(), "--version");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  const auto& v = grainbridge::core::codeVersion();
  EXPECT_NE(r.output.find("grainbridge " + v.release + " (git " + v.gitSha), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(v.dirty ? ", dirty)" : ", clean)"), std::string::npos) << r.output;
  for (const char* pattern : {R"(HDF5 \d+\.\d+\.\d+)", R"(SQLite \d+\.\d+\.\d+)", R"(Eigen \d+\.\d+\.\d+)",
                              R"(MPI: \S+)"}) {
    EXPECT_TRUE(std::regex_search(r.output, std::regex(pattern))) << pattern << "\n" << r.output;
  }
}
