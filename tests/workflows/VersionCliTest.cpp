// `grainbridge --version` (issue 16, item 5): the version, git SHA and dirty flag, and the
// versions of HDF5, SQLite, Eigen and MPI the binary was built with; exit 0 without a
// subcommand (it used to exit 2 with "A subcommand is required").
#include <gtest/gtest.h>

#include <regex>

#include "core/Version.hpp"
#include "engines/lammps/LammpsInput.hpp"
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

// The engines built, and engine lammps's state: "LAMMPS <version>" where liblammps was usable,
// else "off: <why>" (issue 54: a broken liblammps CMake package no longer stops the configure).
TEST(VersionCli, ListsTheEnginesBuilt) {
  TempDir work;
  const auto r = runGrainbridge(work.path(), "--version");
  EXPECT_NE(r.output.find("Engines: dem, mfm, tfdem; lammps: "), std::string::npos) << r.output;
  if (grainbridge::lammps::lammpsAvailable()) {
    EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(lammps: LAMMPS \d+)"))) << r.output;
  } else {
    EXPECT_NE(r.output.find("lammps: off: "), std::string::npos) << r.output;
  }
}

// A mistyped command is named, with the closest one (CLI11 alone said "A subcommand is required").
TEST(VersionCli, UnknownCommandsAreNamedWithASuggestion) {
  TempDir work;
  auto r = runGrainbridge(work.path(), "runn x.json");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("grainbridge: unknown command \"runn\" (did you mean \"run\"?); commands: run, status"),
            std::string::npos)
      << r.output;
  r = runGrainbridge(work.path(), "db quer");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("grainbridge db: unknown command \"quer\" (did you mean \"query\"?)"), std::string::npos)
      << r.output;
}
