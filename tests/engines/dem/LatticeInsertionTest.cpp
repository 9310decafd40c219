// fcc lattice insertion: the requested number of non-overlapping sites inside the box (periodic
// images included), up to solid fractions random insertion cannot reach, and a clear refusal
// beyond what the lattice holds.
#include "engines/dem/LatticeInsertion.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"

using namespace grainbridge;

namespace {

double boxFor(std::size_t n, double solidFraction) {
  return std::cbrt(static_cast<double>(n) * M_PI / 6.0 / solidFraction);
}

}  // namespace

TEST(LatticeInsertion, FillsADenseBoxWithoutOverlapAcrossPeriodicImages) {
  std::mt19937_64 rng(3);
  const std::size_t n = 2000;
  const double L = boxFor(n, 0.55);  // unit diameter
  const auto sites = dem::fccLatticeSites(Vec3::Zero(), Vec3::Constant(L), n, 1.0, rng);
  ASSERT_EQ(sites.size(), n);
  double closest = 1e9;
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) {
      EXPECT_GT(sites[i][d], 0.0);
      EXPECT_LT(sites[i][d], L);
    }
    for (std::size_t j = i + 1; j < n; ++j) {
      Vec3 r = sites[i] - sites[j];
      for (int d = 0; d < 3; ++d) r[d] -= L * std::round(r[d] / L);  // minimum image
      closest = std::min(closest, r.norm());
    }
  }
  EXPECT_GE(closest, 1.0);
}

TEST(LatticeInsertion, VacanciesAreRandomButReproducible) {
  std::mt19937_64 a(1), b(1), c(2);
  const double L = boxFor(100, 0.5);
  EXPECT_EQ(dem::fccLatticeSites(Vec3::Zero(), Vec3::Constant(L), 100, 1.0, a),
            dem::fccLatticeSites(Vec3::Zero(), Vec3::Constant(L), 100, 1.0, b));
  std::mt19937_64 a2(1);
  EXPECT_NE(dem::fccLatticeSites(Vec3::Zero(), Vec3::Constant(L), 100, 1.0, a2),
            dem::fccLatticeSites(Vec3::Zero(), Vec3::Constant(L), 100, 1.0, c));
}

TEST(LatticeInsertion, RefusesABoxTheLatticeCannotHold) {
  std::mt19937_64 rng(1);
  try {
    (void)dem::fccLatticeSites(Vec3::Zero(), Vec3::Constant(boxFor(500, 0.8)), 500, 1.0, rng);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("do not fit on an fcc lattice"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("the densest such lattice has solid fraction about"));
  }
}
