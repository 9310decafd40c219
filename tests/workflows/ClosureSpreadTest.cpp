// The propagation of closure samples (issue 31, workflows/report/ClosureSpread): for an output
// linear in the tables' standard-normal draws, y = y0 + sum_q b_q z_q, the spread over joint
// samples is sqrt(sum_q b_q^2), each quantity's one-at-a-time spread is |b_q| and its share
// b_q^2 / sum b^2. Checked within three standard errors of the estimates over 2000 samples.
#include "workflows/report/ClosureSpread.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "core/Error.hpp"

using grainbridge::workflows::report::ClosureSampleValue;
using grainbridge::workflows::report::closureSpread;

namespace {

const std::map<std::string, double> kSlopes = {{"p_theta", 0.3}, {"eta_theta", 0.1}, {"j_theta", 0.0}};

// `joint` joint samples and `each` one-at-a-time samples of every quantity of the linear output,
// each with its own noise of standard deviation `noise` (a run's fluctuations), stated as its error.
std::vector<ClosureSampleValue> linearSamples(int joint, int each, std::uint64_t seed, double noise = 0.0) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> z;
  std::vector<ClosureSampleValue> out;
  for (int s = 0; s < joint; ++s) {
    double y = 2.0 + noise * z(rng);
    for (const auto& [q, b] : kSlopes) y += b * z(rng);
    out.push_back({"all", y, noise});
  }
  for (const auto& [q, b] : kSlopes) {
    for (int s = 0; s < each; ++s) out.push_back({q, 2.0 + b * z(rng) + noise * z(rng), noise});
  }
  return out;
}

}  // namespace

TEST(ClosureSpread, RecoversTheAnalyticSpreadAndSharesOfALinearOutput) {
  const int n = 2000;
  const auto spread = closureSpread(linearSamples(n, n, 42));
  const double analytic = std::sqrt(0.3 * 0.3 + 0.1 * 0.1);
  // The standard error of a standard deviation over n normal samples: sigma / sqrt(2 (n - 1)).
  const auto se = [n](double sigma) { return sigma / std::sqrt(2.0 * (n - 1)); };
  EXPECT_TRUE(spread.fromJoint);
  EXPECT_EQ(spread.jointSamples, n);
  EXPECT_NEAR(spread.spread, analytic, 3 * se(analytic));
  ASSERT_EQ(spread.quantities.size(), 3u);
  double shares = 0.0;
  for (const auto& q : spread.quantities) {
    const double b = kSlopes.at(q.quantity);
    EXPECT_EQ(q.samples, n);
    EXPECT_NEAR(q.spread, b, 3 * se(b) + 1e-15) << q.quantity;
    // share = a / (a + c) with a, c variances of relative error sqrt(2 / (n - 1)) each.
    const double share = b * b / (analytic * analytic);
    const double shareSe = share * (1 - share) * 2 * std::sqrt(2.0 / (n - 1));
    EXPECT_NEAR(q.share, share, 3 * shareSe + 1e-12) << q.quantity;
    shares += q.share;
  }
  EXPECT_NEAR(shares, 1.0, 1e-12);
  EXPECT_EQ(spread.dominant(), "p_theta");
}

TEST(ClosureSpread, WithoutJointSamplesTheSpreadIsTheRootSumOfSquaresOfTheQuantities) {
  const int n = 2000;
  const auto spread = closureSpread(linearSamples(0, n, 7));
  EXPECT_FALSE(spread.fromJoint);
  const double analytic = std::sqrt(0.3 * 0.3 + 0.1 * 0.1);
  EXPECT_NEAR(spread.spread, analytic, 3 * analytic / std::sqrt(2.0 * (n - 1)));
  // Joint samples alone: the spread without shares.
  const auto joint = closureSpread(linearSamples(n, 0, 9));
  EXPECT_TRUE(joint.quantities.empty());
  EXPECT_EQ(joint.dominant(), "");
}

TEST(ClosureSpread, TooFewSamplesForASpreadAreRefusedSayingWhatItTakes) {
  try {
    (void)closureSpread({{"all", 1.0}, {"p_theta", 1.1}});
    FAIL() << "accepted";
  } catch (const grainbridge::Error& e) {
    EXPECT_NE(std::string(e.what()).find("two joint samples"), std::string::npos) << e.what();
  }
}

// Each run's own fluctuations scatter the samples too: the spread is what is left after their
// stated errors, so it recovers the closures' part alone.
TEST(ClosureSpread, TheRunsOwnNoiseIsTakenOutOfTheScatter) {
  const int n = 2000;
  const double noise = 0.2;
  const auto spread = closureSpread(linearSamples(n, 0, 11, noise));
  const double analytic = std::sqrt(0.3 * 0.3 + 0.1 * 0.1);
  const double total = std::sqrt(analytic * analytic + noise * noise);
  // The standard error of the corrected deviation: that of the total variance, over 2 sqrt(var).
  const double se = total * total * std::sqrt(2.0 / (n - 1)) / (2.0 * analytic);
  EXPECT_NEAR(spread.scatter, total, 3 * total / std::sqrt(2.0 * (n - 1)));
  EXPECT_NEAR(spread.spread, analytic, 3 * se);
  // Noise alone: no spread from the closures, within the estimate's error.
  std::vector<ClosureSampleValue> noiseOnly;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> z;
  for (int s = 0; s < n; ++s) noiseOnly.push_back({"all", 2.0 + noise * z(rng), noise});
  EXPECT_LT(closureSpread(noiseOnly).spread, 3 * noise * std::sqrt(std::sqrt(2.0 / (n - 1))));
}
