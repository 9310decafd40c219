#include <gtest/gtest.h>

#include "core/Sha256.hpp"

TEST(Sha256, MatchesKnownVectors) {
  // FIPS 180-2 test vectors.
  EXPECT_EQ(grainbridge::core::sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(grainbridge::core::sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}
