// Under Lees-Edwards shear the fluctuation velocity is taken about the imposed profile at each
// particle, u_x = gammadot (y - y_mid), so a pure streaming flow has T = 0 in every bin; taking
// it about each bin's constant mean instead (what a frame without the shear rate gets) adds the
// profile's variance within a bin of height h, gammadot^2 h^2 / 36 to T. With thermal noise the
// profile-based T is the noise temperature.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "extract/coarse/CoarseGrain.hpp"
#include "tests/extract/coarse/CoarseTestFrames.hpp"
#include "tests/support/ValidationNote.hpp"
#include "tests/support/ValidationRecord.hpp"

using namespace grainbridge;
using namespace grainbridge::extract::coarse;
using namespace grainbridge::extract::coarse::testing;
using grainbridge::testing::formatNote;
using grainbridge::testing::recordValidation;

namespace {
constexpr const char* kSection = "Kinetic theory against DEM";
constexpr const char* kReference =
    "VALIDATION.md (fluctuations C_i = v_i - u(r_i) about the imposed profile); Eq. 3.38";

constexpr double kShear = 2.0;
constexpr double kL = 10.0;

core::data::ParticleFrame shearedFrame(int n, double noise, std::uint64_t seed) {
  core::data::ParticleFrame f;
  f.domain.lo = Vec3::Zero();
  f.domain.hi = Vec3::Constant(kL);
  f.domain.periodic = {true, true, true};
  f.domain.leesEdwardsShearRate = kShear;
  f.domain.leesEdwardsOffset = 3.7;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, kL);
  std::normal_distribution<double> g(0.0, noise);
  const double yMid = 0.5 * kL;
  for (int i = 0; i < n; ++i) {
    const Vec3 x(u(rng), u(rng), u(rng));
    const Vec3 c = noise > 0.0 ? Vec3(g(rng), g(rng), g(rng)) : Vec3::Zero();
    addParticle(f, i, 0, 0.05, 1.0, x, Vec3(kShear * (x[1] - yMid), 0.0, 0.0) + c);
  }
  return f;
}
}  // namespace

TEST(LeesEdwardsTemperature, PureStreamingHasNoTemperatureAndNoBinArtefact) {
  const auto f = shearedFrame(20000, 0.0, 1);
  const int bins = 5;
  const double h = kL / bins;
  const core::grid::CellGrid grid(f.domain.lo, f.domain.hi, {1, bins, 1}, {true, true, true});
  const auto cg = coarseGrain(f, grid, CoarseGrainingKernel::bin());
  bool streamingPassed = true;
  double streamingWorst = 0.0;  // largest bin temperature
  for (int j = 0; j < bins; ++j) {
    EXPECT_LT(cg.granularTemperature[static_cast<std::size_t>(j)], 1e-24 * kShear * kShear * h * h) << "bin " << j;
    streamingPassed =
        streamingPassed && cg.granularTemperature[static_cast<std::size_t>(j)] < 1e-24 * kShear * kShear * h * h;
    streamingWorst = std::max(streamingWorst, cg.granularTemperature[static_cast<std::size_t>(j)]);
    // The mean velocity is still the lab-frame profile at the bin's mean height.
    EXPECT_NEAR(cg.velocity[static_cast<std::size_t>(j)][0], kShear * ((j + 0.5) * h - 0.5 * kL), 0.05 * kShear * h);
  }
  // The same frame without the shear rate: T about each bin's mean is gammadot^2 h^2 / 36.
  auto plain = f;
  plain.domain.leesEdwardsShearRate = 0.0;
  plain.domain.leesEdwardsOffset = 0.0;
  const auto naive = coarseGrain(plain, grid, CoarseGrainingKernel::bin());
  const double artefact = kShear * kShear * h * h / 36.0;
  bool artefactPassed = true;
  std::size_t farthest = 0;  // the bin farthest from the artefact
  for (int j = 0; j < bins; ++j) {
    // uniform y in the bin: relative sampling error sqrt(0.8 / N_bin) ~ 1.4 %
    EXPECT_NEAR(naive.granularTemperature[static_cast<std::size_t>(j)] / artefact, 1.0, 0.06) << "bin " << j;
    const double ratio = naive.granularTemperature[static_cast<std::size_t>(j)] / artefact;
    artefactPassed = artefactPassed && std::abs(ratio - 1.0) <= 0.06;
    if (std::abs(ratio - 1.0) > std::abs(naive.granularTemperature[farthest] / artefact - 1.0)) {
      farthest = static_cast<std::size_t>(j);
    }
  }
  const std::string setup =
      formatNote("20000 particles streaming at gammadot = %g, %d bins of height h = %g", kShear, bins, h);
  recordValidation({"extract.lees_edwards_temperature.streaming", kSection,
                    "granular temperature of a pure Lees-Edwards streaming flow with C about the imposed profile at "
                    "each particle: largest bin T (no gammadot^2 h^2 / 36 artefact)",
                    kReference, 0.0, streamingWorst, "round-off (1e-24 gammadot^2 h^2)", streamingPassed, setup});
  recordValidation({"extract.lees_edwards_temperature.bin_mean_artefact", kSection,
                    "the same frame with C about each bin's constant mean: bin T against gammadot^2 h^2 / 36 (the "
                    "bin farthest from it shown)",
                    kReference, artefact, naive.granularTemperature[farthest], "6 % (sampling)", artefactPassed,
                    setup + "; relative sampling error sqrt(0.8 / N_bin) ~ 1.4 %"});
  std::printf("bin T without the profile: %.4f (gammadot^2 h^2 / 36 = %.4f); with it: %.2e\n",
              naive.granularTemperature[0], artefact, cg.granularTemperature[0]);
}

TEST(LeesEdwardsTemperature, NoisyShearGivesTheNoiseTemperatureWithEveryKernel) {
  const double noise = 0.3;
  const int n = 20000;
  const auto f = shearedFrame(n, noise, 2);
  const core::grid::CellGrid grid(f.domain.lo, f.domain.hi, {2, 5, 2}, {true, true, true});
  for (const auto& kernel : {CoarseGrainingKernel::bin(), CoarseGrainingKernel::lucy(1.2)}) {
    const auto cg = coarseGrain(f, grid, kernel);
    double sum = 0.0;
    for (double T : cg.granularTemperature) sum += T;
    const double mean = sum / static_cast<double>(grid.cellCount());
    EXPECT_NEAR(mean / (noise * noise), 1.0, 0.03) << kernel.name();  // the artefact would add 0.44
    recordValidation({"extract.lees_edwards_temperature.noise." + kernel.name(), kSection,
                      "Lees-Edwards shear with thermal noise (" + kernel.name() +
                          " kernel): cell-averaged T about the imposed profile against the noise temperature",
                      kReference, noise * noise, mean, "3 %", std::abs(mean / (noise * noise) - 1.0) <= 0.03,
                      formatNote("%d particles, gammadot = %g, 2 x 5 x 2 cells; the bin-mean artefact would add "
                                 "%.3f to T",
                                 n, kShear, kShear * kShear * (kL / 5) * (kL / 5) / 36.0)});
    EXPECT_NEAR(cg.species[0].granularTemperature[3] / cg.granularTemperature[3], 1.0, 1e-12);
  }
}
