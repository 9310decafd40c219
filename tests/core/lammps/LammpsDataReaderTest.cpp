// readLammpsData: a real write_data file (LAMMPS's chute benchmark bed, in ../shared), small
// synthetic files for the id matching, image flags and skipped sections, and one synthetic file
// per error, each of which must name the file and the offending line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <numbers>
#include <string>
#include <vector>

#include "core/io/LammpsDataReader.hpp"
#include "tests/core/io/IoTestSupport.hpp"

namespace grainbridge::core::io {
namespace {

using iotest::expectError;
using iotest::TempDir;

// Three atoms in an order that is neither sorted nor the Velocities order; atom 10 has no
// velocity; a Masses, a Pair Coeffs and a Bonds section (which a sphere file would not have,
// but a hand-edited one may) must be skipped.
const std::string kSample = R"(LAMMPS data file via write_data, version 29 Sep 2021, timestep = 7

3 atoms
2 atom types
0 bonds
-1.0 4.0 xlo xhi
0 2 ylo yhi
0 10 zlo zhi # comment after a header line

Masses

1 1.0
2 2.0

Pair Coeffs # gran/hooke/history

1 200000 50
2 200000 50

Atoms # sphere

30 2 1.5 2.0 0.5 0.25 1.0 1 -2 0
10 1 1.0 1.0 3.9 1.75 9.5 0 0 0
20 1 0.0 3.5 -1.0 2.0 0.0 -1 0 3

Velocities

20 1 2 3 4 5 6
30 -1 -2 -3 -0.5 0.25 0.125

Bonds

1 1 10 20
)";

// 1-based number of the first line containing `needle`.
int lineOf(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::filesystem::path writeFile(const TempDir& dir, const std::string& text, const std::string& name = "bed.data") {
  const auto path = dir.path() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// Reading `text` must fail with the file's path, "line <line of lineNeedle>" and every part.
void expectLineError(const std::string& text, const std::string& lineNeedle, std::initializer_list<std::string> parts) {
  const TempDir dir;
  const auto path = writeFile(dir, text);
  const std::string where = "'" + path.string() + "', line " + std::to_string(lineOf(text, lineNeedle)) + ":";
  expectError([&] { readLammpsData(path); }, {where});
  expectError([&] { readLammpsData(path); }, parts);
}

void expectSample(const LammpsData& d) {
  EXPECT_EQ(d.title, "LAMMPS data file via write_data, version 29 Sep 2021, timestep = 7");
  EXPECT_EQ(d.lo, Vec3(-1.0, 0.0, 0.0));
  EXPECT_EQ(d.hi, Vec3(4.0, 2.0, 10.0));
  EXPECT_EQ(d.atomTypes, 2);
  EXPECT_TRUE(d.hasVelocities);
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d.id, (std::vector<std::int64_t>{30, 10, 20}));  // file order, not sorted
  EXPECT_EQ(d.type, (std::vector<int>{2, 1, 1}));
  EXPECT_EQ(d.diameter, (std::vector<double>{1.5, 1.0, 0.0}));
  EXPECT_EQ(d.density, (std::vector<double>{2.0, 1.0, 3.5}));
  EXPECT_EQ(d.position[0], Vec3(0.5, 0.25, 1.0));
  EXPECT_EQ(d.position[2], Vec3(-1.0, 2.0, 0.0));
  // Velocities are matched by id: 30 is the first atom, 20 the third, 10 has none.
  EXPECT_EQ(d.velocity[0], Vec3(-1.0, -2.0, -3.0));
  EXPECT_EQ(d.angularVelocity[0], Vec3(-0.5, 0.25, 0.125));
  EXPECT_EQ(d.velocity[1], Vec3::Zero());
  EXPECT_EQ(d.angularVelocity[1], Vec3::Zero());
  EXPECT_EQ(d.velocity[2], Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(d.angularVelocity[2], Vec3(4.0, 5.0, 6.0));
  // Image flags are kept apart; unwrapping adds image * box length (5, 2, 10).
  EXPECT_EQ(d.image[0], Vec3i(1, -2, 0));
  EXPECT_EQ(d.image[1], Vec3i::Zero());
  EXPECT_EQ(d.image[2], Vec3i(-1, 0, 3));
  EXPECT_EQ(d.unwrappedPosition(0), Vec3(5.5, -3.75, 1.0));
  EXPECT_EQ(d.unwrappedPosition(1), d.position[1]);
  EXPECT_EQ(d.unwrappedPosition(2), Vec3(-6.0, 2.0, 30.0));
  // LAMMPS sphere density: mass = density * pi/6 * d^3; diameter 0 is a point mass = density.
  EXPECT_DOUBLE_EQ(d.mass(0), 2.0 * std::numbers::pi / 6.0 * 1.5 * 1.5 * 1.5);
  EXPECT_DOUBLE_EQ(d.mass(1), std::numbers::pi / 6.0);
  EXPECT_DOUBLE_EQ(d.mass(2), 3.5);
}

TEST(LammpsDataReader, ReadsChuteBenchmarkBed) {
  const std::filesystem::path path = GRAINBRIDGE_SOURCE_DIR "/../shared/lammps-bench/data.chute";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is missing (CI has ../shared beside the clone)";
  const LammpsData d = readLammpsData(path);
  ASSERT_EQ(d.size(), 32000u);
  EXPECT_EQ(d.atomTypes, 2);
  EXPECT_EQ(d.lo, Vec3::Zero());
  EXPECT_EQ(d.hi, Vec3(40.0, 20.0, 37.2886));
  EXPECT_TRUE(d.hasVelocities);
  // "1 1 1 1 19.4061 6.46569 14.5438 33 0 0"
  EXPECT_EQ(d.id[0], 1);
  EXPECT_EQ(d.type[0], 1);
  EXPECT_EQ(d.diameter[0], 1.0);
  EXPECT_EQ(d.density[0], 1.0);
  EXPECT_EQ(d.position[0], Vec3(19.4061, 6.46569, 14.5438));
  EXPECT_EQ(d.image[0], Vec3i(33, 0, 0));
  EXPECT_EQ(d.unwrappedPosition(0), Vec3(19.4061 + 33 * 40.0, 6.46569, 14.5438));
  EXPECT_DOUBLE_EQ(d.mass(0), std::numbers::pi / 6.0);
  // "1 7.36585 -0.294381 0.0381822 -0.298859 0.876624 -0.389997"
  EXPECT_EQ(d.velocity[0], Vec3(7.36585, -0.294381, 0.0381822));
  EXPECT_EQ(d.angularVelocity[0], Vec3(-0.298859, 0.876624, -0.389997));
  // "4 1 1 1 4.08152 9.76474 20.0732 42 -1 0"
  EXPECT_EQ(d.image[3], Vec3i(42, -1, 0));
  // "32000 2 1 1 25.0318 18.4119 0.491535 0 0 0", at rest
  EXPECT_EQ(d.id.back(), 32000);
  EXPECT_EQ(d.type.back(), 2);
  EXPECT_EQ(d.position.back(), Vec3(25.0318, 18.4119, 0.491535));
  EXPECT_EQ(d.velocity.back(), Vec3::Zero());
  EXPECT_EQ(std::count(d.type.begin(), d.type.end(), 2), 912);
}

TEST(LammpsDataReader, MatchesVelocitiesByIdAndKeepsImageFlags) {
  const TempDir dir;
  expectSample(readLammpsData(writeFile(dir, kSample)));
}

TEST(LammpsDataReader, AcceptsWindowsLineEndings) {
  std::string crlf;
  for (const char c : kSample) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  const TempDir dir;
  expectSample(readLammpsData(writeFile(dir, crlf)));
}

TEST(LammpsDataReader, ImageFlagsAndVelocitiesAreOptional) {
  std::string text = kSample.substr(0, kSample.find("Velocities"));
  text = replaced(text, "30 2 1.5 2.0 0.5 0.25 1.0 1 -2 0", "30 2 1.5 2.0 0.5 0.25 1.0");
  text = replaced(text, "Atoms # sphere", "Atoms");  // no style comment: columns decide
  const TempDir dir;
  const LammpsData d = readLammpsData(writeFile(dir, text));
  ASSERT_EQ(d.size(), 3u);
  EXPECT_FALSE(d.hasVelocities);
  EXPECT_EQ(d.image[0], Vec3i::Zero());
  EXPECT_EQ(d.image[2], Vec3i(-1, 0, 3));
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_EQ(d.velocity[i], Vec3::Zero());
    EXPECT_EQ(d.angularVelocity[i], Vec3::Zero());
  }
}

TEST(LammpsDataReader, ToleratesRoundOffJustOutsideTheBox) {
  // 4.0000001 is 2e-8 of the 5-long box past xhi: rounding, not a misplaced atom.
  const TempDir dir;
  const auto d = readLammpsData(writeFile(dir, replaced(kSample, "3.9 1.75", "4.0000001 1.75")));
  EXPECT_EQ(d.position[1].x(), 4.0000001);
}

TEST(LammpsDataReaderErrors, MissingOrUnreadableFile) {
  const TempDir dir;
  const auto missing = dir.path() / "nope.data";
  expectError([&] { readLammpsData(missing); }, {missing.string(), "does not exist"});
  expectError([&] { readLammpsData(dir.path()); }, {dir.path().string(), "is a directory"});
  const auto gz = writeFile(dir, std::string("\x1f\x8b\x08\x00", 4), "bed.data.gz");
  expectError([&] { readLammpsData(gz); }, {gz.string(), "gzip"});
}

TEST(LammpsDataReaderErrors, WrongAtomCount) {
  // Fewer atom lines than the header says: both line numbers are named.
  const std::string fewer = replaced(kSample, "3 atoms", "4 atoms");
  const TempDir dir;
  const auto path = writeFile(dir, fewer);
  expectError([&] { readLammpsData(path); },
              {path.string(), "Atoms section (line " + std::to_string(lineOf(fewer, "Atoms #")) + ") has 3 atom lines",
               "header (line 3) says 4 atoms"});
  // More: the first extra line is named.
  const std::string more = replaced(kSample, "3 atoms", "2 atoms");
  expectLineError(more, "20 1 0.0 3.5", {"more atom lines than the header's 2 atoms"});
  // A header with atoms and no Atoms section at all.
  const std::string none = kSample.substr(0, kSample.find("Atoms #"));
  const auto path2 = writeFile(dir, none, "none.data");
  expectError([&] { readLammpsData(path2); }, {path2.string(), "no Atoms section"});
}

TEST(LammpsDataReaderErrors, NonNumericField) {
  expectLineError(replaced(kSample, "3.9 1.75", "3.9 abc"), "3.9 abc", {"column 6 (y) is 'abc', not a finite number"});
  expectLineError(replaced(kSample, "3.9 1.75", "3.9 nan"), "3.9 nan", {"column 6 (y) is 'nan'"});
  expectLineError(replaced(kSample, "10 1 1.0", "10 1.5 1.0"), "10 1.5 1.0",
                  {"column 2 (atom-type) is '1.5', not an integer"});
  expectLineError(replaced(kSample, "1.0 1 -2 0", "1.0 1 -2 z"), "1.0 1 -2 z", {"column 10 (iz) is 'z'"});
  expectLineError(replaced(kSample, "20 1 2 3 4 5 6", "20 1 2 3 4 5 6x"), "20 1 2 3 4 5 6x",
                  {"Velocities line, column 7 (wz) is '6x'"});
  expectLineError(replaced(kSample, "-1.0 4.0 xlo xhi", "-1.0 4.0.0 xlo xhi"), "xlo xhi",
                  {"xhi '4.0.0' is not a number"});
  expectLineError(replaced(kSample, "3 atoms", "3.5 atoms"), "3.5 atoms", {"number of atoms '3.5'"});
}

TEST(LammpsDataReaderErrors, WrongColumnCount) {
  expectLineError(replaced(kSample, "3.9 1.75 9.5 0 0 0", "3.9 1.75 9.5 0 0"), "3.9 1.75 9.5 0 0",
                  {"7 columns", "found 9"});
  expectLineError(replaced(kSample, "20 1 2 3 4 5 6", "20 1 2 3"), "20 1 2 3", {"Velocities line has 7 columns"});
}

TEST(LammpsDataReaderErrors, DuplicatedAtomId) {
  const std::string text = replaced(kSample, "20 1 0.0", "30 1 0.0");
  expectLineError(text, "30 1 0.0",
                  {"atom id 30 appears twice (first on line " + std::to_string(lineOf(text, "30 2 1.5")) + ")"});
}

TEST(LammpsDataReaderErrors, VelocityForAnUnknownOrRepeatedId) {
  expectLineError(replaced(kSample, "20 1 2 3 4 5 6", "99 1 2 3 4 5 6"), "99 1 2 3",
                  {"atom id 99", "not in the Atoms section"});
  const std::string twice = replaced(kSample, "30 -1 -2", "20 -1 -2");
  expectLineError(twice, "20 -1 -2",
                  {"atom id 20 given twice (first on line " + std::to_string(lineOf(twice, "20 1 2 3")) + ")"});
  // Velocities must follow Atoms: ids cannot be matched otherwise.
  const std::string velocities = "Velocities\n\n20 1 2 3 4 5 6\n\n";
  const std::string early = replaced(kSample, "Masses\n", velocities + "Masses\n");
  expectLineError(early, "Velocities", {"before the Atoms section"});
}

TEST(LammpsDataReaderErrors, TriclinicBox) {
  const std::string text = replaced(kSample, "0 10 zlo zhi", "0 10 zlo zhi\n0.5 0 0 xy xz yz");
  expectLineError(text, "xy xz yz", {"triclinic", "0.5 0 0", "not supported"});
}

TEST(LammpsDataReaderErrors, AtomOutsideTheBox) {
  expectLineError(replaced(kSample, "3.9 1.75", "4.1 1.75"), "4.1 1.75",
                  {"atom 10 is outside the box: x = 4.0999999999999996 is not in [-1, 4]"});
  expectLineError(replaced(kSample, "1.75 9.5", "1.75 -0.01"), "1.75 -0.01", {"atom 10 is outside the box: z ="});
  // A tighter tolerance turns the round-off case into an error too.
  const TempDir dir;
  const auto path = writeFile(dir, replaced(kSample, "3.9 1.75", "4.0000001 1.75"));
  expectError([&] { readLammpsData(path, 0.0); }, {path.string(), "outside the box"});
}

TEST(LammpsDataReaderErrors, OtherInvalidContent) {
  expectLineError(replaced(kSample, "10 1 1.0", "10 3 1.0"), "10 3 1.0", {"type 3, outside 1..2"});
  expectLineError(replaced(kSample, "10 1 1.0 1.0", "10 1 -1.0 1.0"), "10 1 -1.0", {"(diameter) is '-1.0'"});
  expectLineError(replaced(kSample, "10 1 1.0 1.0", "10 1 1.0 0"), "10 1 1.0 0", {"(density) is '0'"});
  expectLineError(replaced(kSample, "10 1 1.0", "0 1 1.0"), "0 1 1.0", {"(atom-ID) is '0', not a positive integer"});
  expectLineError(replaced(kSample, "Atoms # sphere", "Atoms # atomic"), "Atoms #",
                  {"atom_style 'atomic'", "only atom_style sphere"});
  expectLineError(replaced(kSample, "-1.0 4.0 xlo", "4.0 -1.0 xlo"), "xlo xhi", {"xhi '-1.0' is not greater"});
  // A missing header line is named (no line number: it is the absence that is wrong).
  const TempDir dir;
  const auto path = writeFile(dir, replaced(kSample, "0 2 ylo yhi\n", ""));
  expectError([&] { readLammpsData(path); }, {path.string(), "no 'ylo yhi' line"});
  const auto path2 = writeFile(dir, replaced(kSample, "2 atom types\n", ""), "types.data");
  expectError([&] { readLammpsData(path2); }, {path2.string(), "no 'N atom types' line"});
}

}  // namespace
}  // namespace grainbridge::core::io
