// Spatial correlations (Eq. 6.12) and correlation lengths: independent forces give a flat
// F(r) = 1 (= <f>^2) within the jackknife errors; fields with a known correlation function give
// the decay length that function implies. The pair search underneath is tested against all
// pairs in tests/extract/geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/Error.hpp"
#include "extract/statistics/CorrelationLength.hpp"
#include "extract/statistics/ForceCorrelation.hpp"
#include "extract/statistics/PairCorrelation.hpp"
#include "extract/statistics/VelocityCorrelation.hpp"
#include "tests/extract/statistics/StatisticsTestSupport.hpp"

using namespace grainbridge;
using namespace grainbridge::extract::statistics;
using namespace grainbridge::extract::statistics::testing;
using grainbridge::core::data::Domain;

TEST(ForceCorrelation, IndependentForcesGiveFlatCorrelationEqualToMeanSquared) {
  // Contacts at random points in a periodic box with i.i.d. exponential forces: for i != j,
  // <f_i f_j> = <f>^2 = 1 at every distance.
  std::mt19937_64 rng(2024);
  const Vec3 hi(12, 12, 12);
  std::uniform_real_distribution<double> u(0.0, 12.0);
  std::exponential_distribution<double> force(2.0);
  std::vector<core::data::ParticleFrame> frames;
  for (int f = 0; f < 8; ++f) {
    std::vector<Vec3> pts;
    std::vector<double> fn;
    for (int k = 0; k < 3000; ++k) {
      pts.emplace_back(u(rng), u(rng), u(rng));
      fn.push_back(force(rng));
    }
    frames.push_back(frameWithContacts(pts, fn, rng));
    frames.back().domain = periodicBox(Vec3::Zero(), hi);
  }
  const CorrelationOptions opt{0.25, 3.0, 16};
  for (std::size_t nFrames : {std::size_t{1}, std::size_t{8}}) {
    const auto c = forceCorrelation(std::span(frames).first(nFrames), opt);
    EXPECT_EQ(c.resampling, nFrames == 1 ? "point groups" : "frames");
    EXPECT_NEAR(c.mean, 1.0, 1e-12);              // forces normalised per frame
    for (std::size_t k = 1; k < c.bins(); ++k) {  // the first bin holds few pairs
      ASSERT_TRUE(std::isfinite(c.error[k])) << k;
      EXPECT_LT(std::abs(c.value[k] - 1.0), 4.0 * c.error[k]) << "r = " << c.r[k];
      EXPECT_LT(std::abs(c.normalised[k]), 4.0 * c.normalisedError[k]);
      // Scale of the error from the construction: with f normalised by its frame mean, the
      // fluctuation of F in a bin of P pairs is about sqrt((2 var f + (var f)^2) / P) =
      // sqrt(3 / P) for exponential forces (var f = 1). Bins share points, so their errors are
      // correlated and a chi^2 over bins would not be chi^2-distributed; the band is loose
      // because a jackknife of a pair statistic is conservative (~1.5x here) and, over 8 frames,
      // itself uncertain by ~25 %.
      const double scale = std::sqrt(3.0 / c.pairs[k]);
      EXPECT_GT(c.error[k], 0.4 * scale) << "r = " << c.r[k];
      EXPECT_LT(c.error[k], 3.0 * scale) << "r = " << c.r[k];
    }
    // Pair counts follow the uniform density: pairs in a shell = N (N - 1) / (2 V) * shell volume.
    const double frameCount = static_cast<double>(nFrames), perFrame = 3000.0;
    const std::size_t k = 8;  // [2, 2.25)
    const double shell = 4.0 / 3.0 * M_PI * (std::pow(c.rHi[k], 3) - std::pow(c.rLo[k], 3));
    const double expected = frameCount * perFrame * (perFrame - 1) / 2.0 / (12.0 * 12.0 * 12.0) * shell;
    EXPECT_NEAR(c.pairs[k], expected, 5.0 * std::sqrt(expected));
  }
}

TEST(CorrelationLength, OrnsteinUhlenbeckLineGivesItsExponentialLength) {
  // An Ornstein-Uhlenbeck sequence along x has <w(x) w(x + r)> = e^{-r/xi} exactly; points on a
  // line in an open box, so the 3-d distance is |dx|. C(r) = e^{-r/xi} gives decayLength = xi
  // (from the first bin centre) and the exponential fit xi. 24 frames of 2000 xi: the spread of
  // either estimate over seeds is about 2.3 %, so 0.07 is a 3-sigma bound; the jackknife error of
  // a 1/e crossing is itself uncertain (~20 %), hence both bounds.
  std::mt19937_64 rng(77);
  const double xi = 1.0;
  std::exponential_distribution<double> gap(5.0);  // mean spacing xi / 5
  std::normal_distribution<double> g(0.0, 1.0);
  Domain open;
  CorrelationAccumulator acc({0.05, 3.0, 16}, FrameNormalisation::None, "OU test");
  for (int frame = 0; frame < 24; ++frame) {
    std::vector<Vec3> p;
    std::vector<double> w;
    double x = 0.0, v = g(rng);
    for (int k = 0; k < 10000; ++k) {
      p.emplace_back(x, 0.5, 0.5);
      w.push_back(v);
      const double dx = gap(rng), rho = std::exp(-dx / xi);
      x += dx;
      v = rho * v + std::sqrt(1.0 - rho * rho) * g(rng);
    }
    acc.add(open, p, w);
  }
  const auto c = acc.result();
  EXPECT_EQ(c.resampling, "frames");
  const auto len = decayLength(c);
  EXPECT_NEAR(len.rPeak, 0.025, 1e-12);  // C is largest in the first bin
  ASSERT_TRUE(std::isfinite(len.error));
  EXPECT_GT(len.error, 0.005);  // 24 frames of 2000 xi cannot pin xi better than ~1 %
  EXPECT_LT(len.error, 0.05);
  EXPECT_LT(std::abs(len.length - xi), std::max(3.0 * len.error, 0.07)) << len.length << " +- " << len.error;
  const auto fit = exponentialLength(c);
  ASSERT_TRUE(std::isfinite(fit.lengthError));
  EXPECT_LT(std::abs(fit.length - xi), std::max(3.0 * fit.lengthError, 0.07))
      << fit.length << " +- " << fit.lengthError;
  EXPECT_NEAR(fit.amplitude, std::exp(-0.025 / xi), 3.0 * fit.amplitudeError + 0.01);
}

TEST(CorrelationLength, PeriodicGaussianVelocityFieldGivesItsLength) {
  // Each velocity component is white noise on a lattice of spacing h smoothed by a Gaussian of
  // width s, periodic in the box (minimum image in the smoothing), so the normalised velocity
  // correlation is exp(-r^2 / (4 s^2)) across the periodic faces too. Its 1/e point measured
  // from the first bin centre r0 is sqrt(4 s^2 + r0^2), so xi = sqrt(4 s^2 + r0^2) - r0.
  std::mt19937_64 rng(5);
  const double s = 1.0, h = 1.0, L = 16.0, dr = 0.1, cut = 4.0 * s;
  const int m = static_cast<int>(L / h);
  const Domain box = periodicBox(Vec3::Zero(), Vec3(L, L, L));
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, L);
  std::vector<core::data::ParticleFrame> frames;
  for (int f = 0; f < 4; ++f) {
    std::vector<Vec3> noise(static_cast<std::size_t>(m * m * m));
    for (auto& n : noise) n = Vec3(g(rng), g(rng), g(rng));
    core::data::ParticleFrame frame;
    frame.domain = box;
    const int reach = static_cast<int>(std::ceil(cut / h));
    for (int k = 0; k < 4000; ++k) {
      const Vec3 x(u(rng), u(rng), u(rng));
      Vec3 v = Vec3::Zero();
      const Vec3i c0 = (x / h).array().floor().cast<int>();
      for (int i = -reach; i <= reach + 1; ++i)
        for (int j = -reach; j <= reach + 1; ++j)
          for (int l = -reach; l <= reach + 1; ++l) {
            const Vec3 site = (c0 + Vec3i(i, j, l)).cast<double>() * h;
            const double r2 = (x - site).squaredNorm();
            if (r2 > cut * cut) continue;
            const auto idx = [&](int a) { return ((a % m) + m) % m; };
            v += noise[static_cast<std::size_t>((idx(c0[0] + i) * m + idx(c0[1] + j)) * m + idx(c0[2] + l))] *
                 std::exp(-r2 / (2 * s * s));
          }
      frame.id.push_back(k);
      frame.species.push_back(0);
      frame.radius.push_back(0.5);
      frame.mass.push_back(1.0);
      frame.position.push_back(x);
      frame.velocity.push_back(v);
      frame.angularVelocity.push_back(Vec3::Zero());
    }
    frames.push_back(std::move(frame));
  }
  const auto c = velocityCorrelation(frames, {dr, 5.0, 16});
  EXPECT_EQ(c.resampling, "frames");
  const auto len = decayLength(c, {200.0});
  const double r0 = len.rPeak;
  const double expected = std::sqrt(4 * s * s + r0 * r0) - r0;
  ASSERT_TRUE(std::isfinite(len.error));
  EXPECT_LT(std::abs(len.length - expected), std::max(3.0 * len.error, 0.03 * expected))
      << len.length << " +- " << len.error << " expected " << expected << " (peak at " << r0 << ")";
  EXPECT_LT(std::abs(len.length / expected - 1.0), 0.1);
  // Check the shape, not only the crossing: C(r) = exp(-r^2/4s^2) within 4 jackknife errors plus
  // the bias of removing each frame's sample mean (about the correlation volume over the box
  // volume, (4 pi s^2)^{3/2} / L^3 ~ 1 %).
  for (std::size_t k = 0; k < c.bins(); ++k) {
    if (c.pairs[k] < 200) continue;
    EXPECT_LT(std::abs(c.normalised[k] - std::exp(-c.r[k] * c.r[k] / (4 * s * s))), 4.0 * c.normalisedError[k] + 0.02)
        << "r = " << c.r[k];
  }
}

TEST(CorrelationLength, RefusesCorrelationsThatDoNotDecayWithinRMax) {
  // Perfectly correlated weights along a gradient: C stays near its peak out to r_max.
  Domain open;
  std::vector<Vec3> p;
  std::vector<double> w;
  for (int k = 0; k < 400; ++k) {
    p.emplace_back(0.01 * k, 0.0, 0.0);
    w.push_back(std::sin(0.001 * k));
  }
  CorrelationAccumulator acc({0.1, 0.5, 4}, FrameNormalisation::None, "test");
  acc.add(open, p, w);
  EXPECT_THROW((void)decayLength(acc.result()), Error);
  EXPECT_THROW(CorrelationAccumulator({0.0, 1.0, 4}, FrameNormalisation::None, "test"), Error);
}

TEST(CorrelationAccumulator, RefusesRMaxPastHalfThePeriodicBox) {
  // Past half an edge a pair has two images within r_max, and Eq. 6.12 counts each pair once.
  const Domain box = periodicBox(Vec3(-1, 0, 2), Vec3(9, 8, 10));
  const std::vector<Vec3> p{Vec3(0, 1, 3), Vec3(1, 2, 4)};
  const std::vector<double> w{1.0, 2.0};
  CorrelationAccumulator wide({0.1, 4.5, 4}, FrameNormalisation::None, "test");  // > half the 8-long y and z edges
  EXPECT_THROW(wide.add(box, p, w), Error);
  CorrelationAccumulator half({0.1, 4.0, 4}, FrameNormalisation::None, "test");
  EXPECT_NO_THROW(half.add(box, p, w));
}
