// The checkpoint header every engine shares (core/io/CheckpointFile): the content written
// through the callback comes back exactly, a file of another format version or another
// configuration is refused with the message the engines always gave, two engines' states sit
// in one file each in its own group, and a failed write leaves the previous checkpoint intact.
#include <gtest/gtest.h>

#include <stdexcept>

#include "core/io/CheckpointFile.hpp"
#include "core/io/H5Path.hpp"
#include "tests/core/io/IoTestSupport.hpp"

namespace grainbridge::core::io {
namespace {

using iotest::expectError;
using iotest::TempDir;

// A stand-in for an engine's state, written into `group`.
void writeState(H5OutputFile& f, const std::string& group, double time, const std::vector<double>& values) {
  if (group != "/") f.createGroup(group);
  f.writeAttribute(group, "time", time);
  f.writeDataset(memberPath(group, "values"), values);
}

TEST(CheckpointFile, RoundTripKeepsHeaderAndContent) {
  const TempDir dir;
  const auto path = dir.path() / "state.h5";
  const std::vector<double> values{0.1, 1.0 / 3.0, -2.5e-17};
  writeCheckpointFile(path, {7, "key-abc"}, [&](H5OutputFile& f) { writeState(f, "/", 1.25, values); });
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  const H5InputFile f = openCheckpointFile(path, {7, "key-abc"});
  EXPECT_EQ(f.readIntAttribute("/", "format_version"), 7);
  EXPECT_EQ(f.readStringAttribute("/", "fingerprint"), "key-abc");
  EXPECT_EQ(f.readDoubleAttribute("/", "time"), 1.25);
  EXPECT_EQ(f.readDoubles("/values", {3}), values);
}

TEST(CheckpointFile, AnotherFormatVersionOrConfigurationIsRefused) {
  const TempDir dir;
  const auto path = dir.path() / "state.h5";
  writeCheckpointFile(path, {3, "key"}, [](H5OutputFile&) {});
  expectError(
      [&] {
        static_cast<void>(openCheckpointFile(path, {2, "key"}));
      },
      {"checkpoint '" + path.string() + "' has format_version 3, this build reads 2"});
  expectError(
      [&] {
        static_cast<void>(openCheckpointFile(path, {3, "another key"}));
      },
      {"checkpoint '" + path.string() + "' belongs to another configuration"});
}

TEST(CheckpointFile, TwoStatesInOneFileEachInItsGroup) {
  const TempDir dir;
  const auto path = dir.path() / "coupled.h5";
  writeCheckpointFile(path, {1, "coupled"}, [](H5OutputFile& f) {
    writeState(f, "/dem", 0.5, {1.0, 2.0, 3.0});
    writeState(f, "/fluid", 0.75, {4.0, 5.0});
  });
  const H5InputFile f = openCheckpointFile(path, {1, "coupled"});
  EXPECT_EQ(f.readDoubleAttribute("/dem", "time"), 0.5);
  EXPECT_EQ(f.readDoubles("/dem/values", {3}), (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_EQ(f.readDoubleAttribute("/fluid", "time"), 0.75);
  EXPECT_EQ(f.readDoubles("/fluid/values", {2}), (std::vector<double>{4.0, 5.0}));
  EXPECT_FALSE(f.hasAttribute("/", "time"));
}

TEST(CheckpointFile, FailedWriteKeepsThePreviousCheckpoint) {
  const TempDir dir;
  const auto path = dir.path() / "state.h5";
  writeCheckpointFile(path, {2, "key"}, [](H5OutputFile& f) { writeState(f, "/", 1.0, {1.0}); });
  EXPECT_THROW(writeCheckpointFile(path, {2, "key"},
                                   [](H5OutputFile& f) {
                                     writeState(f, "/", 2.0, {2.0});
                                     throw std::runtime_error("disk full");
                                   }),
               std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  const H5InputFile f = openCheckpointFile(path, {2, "key"});
  EXPECT_EQ(f.readDoubleAttribute("/", "time"), 1.0);
}

}  // namespace
}  // namespace grainbridge::core::io
