#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/Sha256.hpp"

TEST(Sha256, MatchesKnownVectors) {
  // FIPS 180-2 test vectors.
  EXPECT_EQ(grainbridge::core::sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(grainbridge::core::sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

// An input file's digest is computed once per version (path, size, modification time) and is the
// file's digest: a file rewritten with other bytes of the same size gets its new digest.
TEST(Sha256, OncePerVersionFollowsTheFile) {
  namespace fs = std::filesystem;
  const fs::path file = fs::temp_directory_path() / ("gb-sha256-once-" + std::to_string(::getpid()) + ".txt");
  auto write = [&](const char* text) {
    std::ofstream(file, std::ios::binary) << text;
  };
  write("abc");
  EXPECT_EQ(grainbridge::core::sha256FileOncePerVersion(file), grainbridge::core::sha256File(file));
  EXPECT_EQ(grainbridge::core::sha256FileOncePerVersion(file), grainbridge::core::sha256Hex("abc"));
  const auto written = fs::last_write_time(file);
  write("abd");
  fs::last_write_time(file, written + std::chrono::seconds(1));
  EXPECT_EQ(grainbridge::core::sha256FileOncePerVersion(file), grainbridge::core::sha256Hex("abd"));
  fs::remove(file);
}
