// The one Maxwellian initialisation the particle_gas and dem stages share (issue 14): zero total
// momentum and exactly the asked granular temperature T = <C^2>/3 (Eq. 3.38), components that
// look normal, the same draws for the same seed, and zeros where no temperature can be carried.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engines/dem/MaxwellianVelocities.hpp"

using namespace grainbridge;

TEST(MaxwellianVelocities, HaveZeroMomentumAndExactlyTheAskedTemperature) {
  std::mt19937_64 rng(7);
  const std::size_t n = 4000;
  const double T = 2.5e-3;
  const auto v = dem::maxwellianVelocities(n, T, rng);
  ASSERT_EQ(v.size(), n);
  Vec3 sum = Vec3::Zero();
  double c2 = 0.0, c4x = 0.0;
  for (const auto& c : v) {
    sum += c;
    c2 += c.squaredNorm();
    c4x += std::pow(c.x(), 4);
  }
  EXPECT_LT(sum.norm(), 1e-12 * std::sqrt(T) * static_cast<double>(n));
  EXPECT_NEAR(c2 / (3.0 * static_cast<double>(n)), T, 1e-14 * T);
  // A normal component has kurtosis <C^4> / <C^2>^2 = 3 (sampling error ~ sqrt(96 / n) ~ 0.15).
  EXPECT_NEAR(c4x / static_cast<double>(n) / (T * T), 3.0, 0.5);
  std::mt19937_64 again(7);
  EXPECT_EQ(dem::maxwellianVelocities(n, T, again), v);
}

TEST(MaxwellianVelocities, AreZeroWithoutATemperatureToCarry) {
  std::mt19937_64 rng(1);
  for (const auto& c : dem::maxwellianVelocities(10, 0.0, rng)) EXPECT_EQ(c, Vec3::Zero());
  for (const auto& c : dem::maxwellianVelocities(1, 1.0, rng)) EXPECT_EQ(c, Vec3::Zero());
}
