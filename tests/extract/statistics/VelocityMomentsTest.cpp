// Velocity-distribution moments (Section 8.2.1.1): kurtosis <C^4>/<C^2>^2 is 3 for Gaussian
// (Maxwellian) samples and 1.8 for uniform ones, with delta-method errors that match the
// analytic large-N variances; frames are reduced to fluctuations about the mean and, under
// Lees-Edwards shear, about the streaming profile.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/Error.hpp"
#include "extract/statistics/SampleMoments.hpp"
#include "extract/statistics/VelocityMoments.hpp"

using namespace grainbridge;
using namespace grainbridge::extract::statistics;

TEST(SampleMoments, GaussianKurtosisIsThree) {
  std::mt19937_64 rng(8);
  std::normal_distribution<double> g(0.7, 2.0);
  std::vector<double> x(100000);
  for (double& v : x) v = g(rng);
  const auto m = sampleMoments(x);
  const double n = static_cast<double>(x.size());
  // Large-N variances for a Gaussian: var(kurtosis) = 24/N, var(skewness) = 6/N, var(m2) = 2 s^4/N.
  EXPECT_NEAR(m.kurtosisError, std::sqrt(24.0 / n), 0.1 * std::sqrt(24.0 / n));
  EXPECT_NEAR(m.skewnessError, std::sqrt(6.0 / n), 0.1 * std::sqrt(6.0 / n));
  EXPECT_NEAR(m.varianceError, std::sqrt(2.0 / n) * 4.0, 0.1 * std::sqrt(2.0 / n) * 4.0);
  EXPECT_LT(std::abs(m.kurtosis - 3.0), 4.0 * m.kurtosisError) << m.kurtosis;
  EXPECT_LT(std::abs(m.skewness), 4.0 * m.skewnessError);
  EXPECT_LT(std::abs(m.variance - 4.0), 4.0 * m.varianceError);
  EXPECT_NEAR(m.mean, 0.7, 4.0 * 2.0 / std::sqrt(n));
}

TEST(SampleMoments, UniformKurtosisIsNineFifths) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> x(100000);
  for (double& v : x) v = u(rng);
  const auto m = sampleMoments(x);
  const double n = static_cast<double>(x.size());
  // Moments of U(-1, 1): m2 = 1/3, m4 = 1/5, m6 = 1/7, m8 = 1/9; kurtosis 9/5. Delta method
  // (odd moments vanish): N var(K) = (m8 - m4^2)/m2^4 - 4 m4 (m6 - m2 m4)/m2^5 + 4 m4^2 (m4 - m2^2)/m2^6.
  const double m2 = 1.0 / 3, m4 = 1.0 / 5, m6 = 1.0 / 7, m8 = 1.0 / 9;
  const double varK = ((m8 - m4 * m4) / std::pow(m2, 4) - 4 * m4 * (m6 - m2 * m4) / std::pow(m2, 5) +
                       4 * m4 * m4 * (m4 - m2 * m2) / std::pow(m2, 6)) /
                      n;
  EXPECT_NEAR(m.kurtosisError, std::sqrt(varK), 0.1 * std::sqrt(varK));
  EXPECT_LT(std::abs(m.kurtosis - 1.8), 4.0 * m.kurtosisError) << m.kurtosis;
  EXPECT_LT(std::abs(m.variance - 1.0 / 3.0), 4.0 * m.varianceError);
  EXPECT_THROW((void)sampleMoments(std::vector<double>{1.0}), Error);
  EXPECT_THROW((void)sampleMoments(std::vector<double>{2.0, 2.0, 2.0}), Error);
}

TEST(VelocityMoments, FluctuationsAboutMeanAndShearProfilePerSpecies) {
  // Species 0: Maxwellian with per-component widths (0.5, 1, 2) on top of a drift and the
  // Lees-Edwards streaming profile u_x = gammadot (y - y_mid); species 1: uniform, width 3.
  std::mt19937_64 rng(10);
  core::data::ParticleFrame f;
  f.domain.lo = Vec3::Zero();
  f.domain.hi = Vec3(20, 20, 20);
  f.domain.periodic = {true, true, true};
  f.domain.leesEdwardsShearRate = 0.5;
  f.domain.leesEdwardsOffset = 1.0;
  const Vec3 sigma(0.5, 1.0, 2.0), drift(3.0, -1.0, 0.25);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> pos(0.0, 20.0), uni(-3.0, 3.0);
  for (int k = 0; k < 60000; ++k) {
    const int species = k % 3 == 0 ? 1 : 0;
    const Vec3 x(pos(rng), pos(rng), pos(rng));
    Vec3 v = species == 0 ? Vec3(sigma[0] * g(rng), sigma[1] * g(rng), sigma[2] * g(rng))
                          : Vec3(uni(rng), uni(rng), uni(rng));
    v += drift;
    v[0] += 0.5 * (x[1] - 10.0);
    f.id.push_back(k);
    f.species.push_back(species);
    f.radius.push_back(0.5);
    f.mass.push_back(1.0);
    f.position.push_back(x);
    f.velocity.push_back(v);
    f.angularVelocity.push_back(Vec3::Zero());
  }
  const auto m0 = velocityMoments(std::span(&f, 1), {0});
  EXPECT_EQ(m0.samples, 40000u);
  for (std::size_t a = 0; a < 3; ++a) {
    const auto& c = m0.component[a];
    EXPECT_NEAR(c.mean, 0.0, 1e-12);  // fluctuations are about the mean
    EXPECT_LT(std::abs(c.variance - sigma[static_cast<Eigen::Index>(a)] * sigma[static_cast<Eigen::Index>(a)]),
              4.0 * c.varianceError)
        << a;
    EXPECT_LT(std::abs(c.kurtosis - 3.0), 4.0 * c.kurtosisError) << a;
  }
  const auto m1 = velocityMoments(std::span(&f, 1), {1});
  for (const auto& c : m1.component) {
    EXPECT_LT(std::abs(c.variance - 3.0), 4.0 * c.varianceError);  // width 6: 36/12
    EXPECT_LT(std::abs(c.kurtosis - 1.8), 4.0 * c.kurtosisError);
  }
  EXPECT_THROW((void)velocityMoments(std::span(&f, 1), {7}), Error);  // no particle of species 7
}

TEST(VelocityMoments, PlanarComponentWithoutSpreadIsReportedNotRefused) {
  std::mt19937_64 rng(12);
  std::normal_distribution<double> g(0.0, 1.0);
  core::data::ParticleFrame f;
  for (int k = 0; k < 1000; ++k) {
    f.id.push_back(k);
    f.species.push_back(0);
    f.radius.push_back(0.5);
    f.mass.push_back(1.0);
    f.position.push_back(Vec3(k, 0, 0));
    f.velocity.push_back(Vec3(g(rng), g(rng), 0.0));
    f.angularVelocity.push_back(Vec3::Zero());
  }
  const auto m = velocityMoments(std::span(&f, 1));
  EXPECT_EQ(m.component[2].variance, 0.0);
  EXPECT_TRUE(std::isnan(m.component[2].kurtosis));
  EXPECT_TRUE(std::isfinite(m.component[0].kurtosis));
}
