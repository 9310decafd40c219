// The theta forms' errors and correlations from the frame series (extract/observe/ThetaFormErrors,
// issue 63), checked against the spread over independent realisations of a synthetic sheared
// gas: a temperature correlated from frame to frame (AR(1), 0.8 at one frame), a kinetic pressure
// that follows it frame by frame plus a white contact part, and a white shear stress. The
// quadrature sum of relative errors overstates p_theta's error (p and theta move together); the
// series' error matches the spread, and eta_theta and j_theta, which share tau, come out
// correlated as their realisations are.
#include "extract/observe/ThetaFormErrors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/Error.hpp"
#include "core/averaging/BlockAverage.hpp"

using namespace grainbridge;
using namespace grainbridge::extract::observe;

namespace {

struct Frames {
  std::vector<double> temperature, pressure, shearStress;
};

Frames shearedGas(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  Frames f;
  const double rho = 0.8;
  double x = g(rng);
  for (std::size_t k = 0; k < n; ++k) {
    x = rho * x + std::sqrt(1 - rho * rho) * g(rng);
    const double theta = 0.02 * (1.0 + 0.05 * x);  // m2/s2, 5 % fluctuations
    f.temperature.push_back(theta);
    f.pressure.push_back(2500.0 * 0.2 * theta * 1.8 + 0.5 * g(rng));  // kinetic part follows theta
    f.shearStress.push_back(6.0 + 1.5 * g(rng));
  }
  return f;
}

double sd(const std::vector<double>& v) {
  double m = 0.0, s = 0.0;
  for (double x : v) m += x;
  m /= static_cast<double>(v.size());
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size() - 1));
}

}  // namespace

TEST(ThetaFormErrors, MatchTheSpreadOfIndependentRealisationsAndTheirCorrelation) {
  const core::ClosureFormState state{2500.0, 1e-3, 0.02, 100.0};
  const std::size_t realisations = 400, frames = 400;
  std::vector<double> p, eta, j, pErr, etaErr, jErr, quadrature, corrEtaJ, corrPEta;
  for (std::size_t r = 0; r < realisations; ++r) {
    const auto f = shearedGas(frames, 7 + r);
    std::vector<double> viscosity, work;
    for (double tau : f.shearStress) {
      viscosity.push_back(tau / state.shearRate);
      work.push_back(tau * state.shearRate);
    }
    const std::vector<ThetaFormSeries> forms{{core::ClosureForm::PTheta, f.pressure},
                                             {core::ClosureForm::EtaTheta, viscosity},
                                             {core::ClosureForm::JTheta, work}};
    const auto e = thetaFormErrors(forms, f.temperature, state);
    ASSERT_EQ(e.forms.size(), 3u);
    ASSERT_EQ(e.correlations.size(), 3u);
    p.push_back(e.forms[0].value);
    eta.push_back(e.forms[1].value);
    j.push_back(e.forms[2].value);
    pErr.push_back(e.forms[0].error);
    etaErr.push_back(e.forms[1].error);
    jErr.push_back(e.forms[2].error);
    EXPECT_EQ(e.correlations[0].first, "p_theta");
    EXPECT_EQ(e.correlations[0].second, "eta_theta");
    corrPEta.push_back(e.correlations[0].coefficient);
    corrEtaJ.push_back(e.correlations[2].coefficient);
    // The quadrature sum core::closureFormError gives from the two means' own block errors.
    const auto bp = core::averaging::blockAverage(f.pressure), bt = core::averaging::blockAverage(f.temperature);
    quadrature.push_back(core::closureFormError(core::ClosureForm::PTheta, {bp.mean, bp.standardError},
                                                {bt.mean, bt.standardError}, state));
  }
  const auto mean = [](const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v) m += x;
    return m / static_cast<double>(v.size());
  };
  // The spread of 400 realisations is known to about 3.5 %; the mean reported error to better.
  EXPECT_NEAR(mean(pErr) / sd(p), 1.0, 0.12);
  EXPECT_GT(mean(quadrature) / sd(p), 1.3);  // the independent-errors sum overstates it
  EXPECT_NEAR(mean(etaErr) / sd(eta), 1.0, 0.12);
  EXPECT_NEAR(mean(jErr) / sd(j), 1.0, 0.12);
  // The correlations of the realised forms against the mean recorded coefficients.
  const auto correlation = [&](const std::vector<double>& a, const std::vector<double>& b) {
    const double ma = mean(a), mb = mean(b);
    double c = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) c += (a[k] - ma) * (b[k] - mb);
    return c / static_cast<double>(a.size() - 1) / (sd(a) * sd(b));
  };
  EXPECT_NEAR(mean(corrEtaJ), correlation(eta, j), 0.1);
  EXPECT_NEAR(mean(corrPEta), correlation(p, eta), 0.1);
  EXPECT_GT(mean(corrEtaJ), 0.5);  // they share tau
  std::printf(
      "p_theta SE %.4g, quadrature %.4g (spread %.4g); eta-j correlation %.3f (realised %.3f), p-eta %.3f (%.3f)\n",
      mean(pErr), mean(quadrature), sd(p), mean(corrEtaJ), correlation(eta, j), mean(corrPEta), correlation(p, eta));
}

TEST(ThetaFormErrors, RefuseSeriesOfDifferentLengths) {
  const std::vector<double> t{1.0, 1.1, 0.9}, p{1.0, 2.0};
  const std::vector<ThetaFormSeries> forms{{core::ClosureForm::PTheta, p}};
  EXPECT_THROW((void)thetaFormErrors(forms, t, {1.0, 1.0, 1.0, 0.0}), Error);
  EXPECT_EQ(correlationColumn("p_theta", "j_theta"), "p_theta_j_theta_corr");
}
