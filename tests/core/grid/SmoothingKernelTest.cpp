// Smooth kernels: unit integral over space, per-axis variance w^2 for Lucy (the definition of
// its width) and 0.918 w^2 for the Gaussian truncated at 3w, compact support, errors for bad widths.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "core/grid/SmoothingKernel.hpp"

using namespace grainbridge;
using namespace grainbridge::core::grid;

namespace {
// Radial moments integral_0^c 4 pi r^(2+p) phi(r) dr by composite Simpson (the integrands
// are smooth inside the support).
template <class K>
double radialMoment(const K& k, int p) {
  const int panels = 20000;
  const double h = k.cutoff() / panels;
  const auto f = [&](double r) {
    return 4.0 * M_PI * std::pow(r, 2 + p) * (r < k.cutoff() ? k(r) : k(r * (1 - 1e-16)));
  };
  double sum = f(0.0) + f(k.cutoff() * (1 - 1e-15));
  for (int i = 1; i < panels; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * f(i * h);
  return sum * h / 3.0;
}
}  // namespace

TEST(SmoothingKernel, IntegralOverSpaceIsOne) {
  for (double w : {0.3, 1.0, 2.5}) {
    EXPECT_NEAR(radialMoment(GaussianKernel(w), 0), 1.0, 1e-13);
    EXPECT_NEAR(radialMoment(LucyKernel(w), 0), 1.0, 1e-13);
  }
}

TEST(SmoothingKernel, WidthIsThePerAxisStandardDeviation) {
  const double w = 0.7;
  // <x^2> = <r^2> / 3.
  EXPECT_NEAR(radialMoment(LucyKernel(w), 2) / 3.0, w * w, 1e-13);
  // Truncation at 3w trims the Gaussian's per-axis variance to 0.9178 w^2.
  EXPECT_NEAR(radialMoment(GaussianKernel(w), 2) / 3.0 / (w * w), 0.91782, 1e-5);
  EXPECT_NEAR(LucyKernel(w).cutoff(), 2.0 * std::sqrt(3.0) * w, 1e-15);
  EXPECT_NEAR(GaussianKernel(w).cutoff(), 3.0 * w, 1e-15);
}

TEST(SmoothingKernel, CompactSupportAndLucyFormula) {
  const LucyKernel lucy(0.5);
  const double c = lucy.cutoff();
  EXPECT_EQ(lucy(c), 0.0);
  EXPECT_EQ(lucy(1.1 * c), 0.0);
  EXPECT_NEAR(lucy(0.0), 105.0 / (16.0 * M_PI * c * c * c), 1e-15);
  const double s = 0.4;
  EXPECT_NEAR(lucy(s * c), 105.0 / (16.0 * M_PI * c * c * c) * (1 + 3 * s) * std::pow(1 - s, 3), 1e-15);
  const GaussianKernel gauss(0.5);
  EXPECT_EQ(gauss(1.5), 0.0);
  EXPECT_GT(gauss(1.4999), 0.0);
}

TEST(SmoothingKernel, NonPositiveWidthIsAnError) {
  try {
    GaussianKernel k(0.0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("gaussian width 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(LucyKernel(-1.0), Error);
  EXPECT_THROW(LucyKernel(std::nan("")), Error);
}
