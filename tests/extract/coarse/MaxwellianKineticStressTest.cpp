// Kinetic part of Eq. 2.3 for a Maxwellian gas: equals n m T I within sampling error, and equals
// the sample estimate (1/V) sum m C C with T the sample temperature (Eq. 3.38) to round-off;
// per-species temperatures of a binary gas in equipartition both come out T.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "extract/coarse/CoarseGrain.hpp"
#include "extract/coarse/DomainAverages.hpp"
#include "tests/extract/coarse/CoarseTestFrames.hpp"
#include "tests/support/ValidationNote.hpp"
#include "tests/support/ValidationRecord.hpp"

using namespace grainbridge;
using namespace grainbridge::extract::coarse;
using namespace grainbridge::extract::coarse::testing;

namespace {
constexpr double kT = 0.7;
constexpr double kSide = 20.0;

// n particles of two species (mass 1 and 3, alternating), Maxwellian at T = kT about a drift.
core::data::ParticleFrame gas(int n, std::uint64_t seed) {
  core::data::ParticleFrame f;
  f.domain.lo = Vec3::Zero();
  f.domain.hi = Vec3::Constant(kSide);
  f.domain.periodic = {true, true, true};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, kSide);
  std::normal_distribution<double> g(0.0, 1.0);
  const Vec3 drift(0.3, -0.2, 0.1);
  for (int i = 0; i < n; ++i) {
    const int species = i % 2;
    const double m = species == 0 ? 1.0 : 3.0;
    // Eq. 3.38 defines T = <C^2>/3, a velocity variance: both species get the same one.
    const Vec3 v = drift + std::sqrt(kT) * Vec3(g(rng), g(rng), g(rng));
    addParticle(f, i, species, 0.1, m, Vec3(u(rng), u(rng), u(rng)), v);
  }
  return f;
}
}  // namespace

TEST(MaxwellianKineticStress, EqualsNmTIdentityWithinSamplingAndTheSampleEstimateExactly) {
  const int n = 20000;
  const auto f = gas(n, 42);
  const auto avg = averageWholeDomain(f);
  const double volume = kSide * kSide * kSide;

  // The sample estimate, computed here independently.
  double mass = 0.0;
  Vec3 momentum = Vec3::Zero();
  for (std::size_t i = 0; i < f.size(); ++i) {
    mass += f.mass[i];
    momentum += f.mass[i] * f.velocity[i];
  }
  const Vec3 mean = momentum / mass;
  Mat3 sample = Mat3::Zero();
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Vec3 C = f.velocity[i] - mean;
    sample += f.mass[i] * C * C.transpose();
  }
  sample /= volume;
  const double sampleT = sample.trace() * volume / (3.0 * mass);
  EXPECT_LT((avg.kineticStress - sample).norm(), 1e-12 * sample.norm());
  EXPECT_NEAR(avg.granularTemperature / sampleT, 1.0, 1e-12);
  EXPECT_NEAR(avg.pressure / (mass / volume * sampleT), 1.0, 1e-12);  // tr/3 = rho T exactly
  EXPECT_TRUE(avg.contactStress.isZero());
  const double sampleError = (avg.kineticStress - sample).norm() / sample.norm();
  grainbridge::testing::recordValidation(
      {"extract.kinetic_stress.maxwellian.sample", "Extraction (Section 2.3, Sections 6.3.2-6.3.3)",
       "kinetic part of Eq. 2.3 for a Maxwellian binary gas: pressure tr(sigma_k)/3 against n m T with T = <C^2>/3 "
       "of the sample (Eq. 3.38)",
       "Eq. 2.3, Eq. 3.38", mass / volume * sampleT, avg.pressure, "round-off (1e-12)",
       sampleError < 1e-12 && std::abs(avg.granularTemperature / sampleT - 1.0) <= 1e-12 &&
           std::abs(avg.pressure / (mass / volume * sampleT) - 1.0) <= 1e-12 && avg.contactStress.isZero(),
       grainbridge::testing::formatNote("whole tensor against (1/V) sum m C C^T: relative Frobenius error %.1e; "
                                        "%d particles of masses 1 and 3",
                                        sampleError, n)});

  // Against the ensemble value rho T I: diagonal relative error sqrt(2/N), off-diagonal sqrt(1/N),
  // here with mass weights (masses 1 and 3) inflating both by sqrt(<m^2>)/<m> = 1.12.
  const double rhoT = mass / volume * kT;
  const double rel = 1.12 / std::sqrt(static_cast<double>(n));
  bool ensemblePassed = true;
  double worstSigmas = 0.0;  // largest |component - n m T delta| in units of its sampling error
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      const double tol = 4.0 * rhoT * rel * (a == b ? std::sqrt(2.0) : 1.0);
      EXPECT_NEAR(avg.kineticStress(a, b), a == b ? rhoT : 0.0, tol) << a << b;
      ensemblePassed = ensemblePassed && std::abs(avg.kineticStress(a, b) - (a == b ? rhoT : 0.0)) <= tol;
      worstSigmas = std::max(worstSigmas, 4.0 * std::abs(avg.kineticStress(a, b) - (a == b ? rhoT : 0.0)) / tol);
    }
  }
  grainbridge::testing::recordValidation(
      {"extract.kinetic_stress.maxwellian", "Extraction (Section 2.3, Sections 6.3.2-6.3.3)",
       "kinetic part of Eq. 2.3 for a Maxwellian binary gas equals n m T I: pressure tr(sigma_k)/3 against n m T of "
       "the ensemble (T = 0.7)",
       "Eq. 2.3", rhoT, avg.kineticStress.trace() / 3.0, "4 sigma of sampling (every component)", ensemblePassed,
       grainbridge::testing::formatNote("%d particles; sampling error sqrt(2/N) on the diagonal, sqrt(1/N) off it, "
                                        "times 1.12 for the mass weights; largest component deviation %.2f sigma",
                                        n, worstSigmas)});
  ASSERT_EQ(avg.species.size(), 2u);
  for (const auto& s : avg.species) {
    EXPECT_NEAR(s.granularTemperature / kT, 1.0, 4.0 * std::sqrt(2.0 / 3.0 / (n / 2))) << s.species;
    EXPECT_NEAR(s.solidFraction, (n / 2) * sphereVolume(0.1) / volume, 1e-15);
  }
}

TEST(MaxwellianKineticStress, PerCellTemperatureAboutTheLocalMean) {
  // With C about each bin's own mass-weighted mean, a bin of N_c particles has expected
  // temperature T (1 - <m^2> / (N_c <m>^2)) = T (1 - 1.25 / N_c) for masses 1 and 3.
  const int n = 16000;
  const auto f = gas(n, 7);
  const core::grid::CellGrid grid(f.domain.lo, f.domain.hi, {4, 4, 4}, {true, true, true});
  const auto cg = coarseGrain(f, grid, CoarseGrainingKernel::bin());
  double sumT = 0.0, sumP = 0.0;
  for (std::size_t c = 0; c < grid.cellCount(); ++c) {
    sumT += cg.granularTemperature[c];
    sumP += cg.pressure[c];
    EXPECT_NEAR(cg.granularTemperature[c] * 3.0 * cg.density[c], cg.kineticStress[c].trace(), 1e-12);
  }
  const double perCell = static_cast<double>(n) / static_cast<double>(grid.cellCount());
  const double expected = kT * (1.0 - 1.25 / perCell);
  EXPECT_NEAR(sumT / grid.cellCount() / expected, 1.0, 4.0 * 1.12 * std::sqrt(2.0 / 3.0 / n));
  EXPECT_GT(sumP, 0.0);
}
