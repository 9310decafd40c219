// The integral of the coarse-grained solid fraction over a periodic grid is the total particle
// volume to round-off for every kernel (bin, overlap, Gaussian, Lucy), with or without a
// Lees-Edwards offset, and per species.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "extract/coarse/CoarseGrain.hpp"
#include "tests/extract/coarse/CoarseTestFrames.hpp"
#include "tests/support/ValidationNote.hpp"
#include "tests/support/ValidationRecord.hpp"

using namespace grainbridge;
using namespace grainbridge::extract::coarse;
using namespace grainbridge::extract::coarse::testing;

TEST(SolidFractionIntegral, EqualsTheTotalParticleVolumeForEveryKernel) {
  core::data::ParticleFrame f;
  f.domain.lo = Vec3(-1, 0, 2);
  f.domain.hi = Vec3(5, 4, 7);
  f.domain.periodic = {true, true, true};
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double volume[2] = {0.0, 0.0};
  for (int i = 0; i < 150; ++i) {
    const int s = i % 3 == 0 ? 1 : 0;
    const double r = s == 1 ? 0.45 : 0.2 + 0.1 * u(rng);
    const Vec3 x = f.domain.lo + (f.domain.hi - f.domain.lo).cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
    addParticle(f, 1000 + i, s == 1 ? 7 : 3, r, 1.0, x, Vec3(u(rng), 0, 0));
    volume[s] += sphereVolume(r);
  }
  const core::grid::CellGrid grid(f.domain.lo, f.domain.hi, {6, 5, 4}, {true, true, true});
  for (double offset : {0.0, 2.3}) {
    f.domain.leesEdwardsOffset = offset;
    for (const auto& kernel : {CoarseGrainingKernel::bin(), CoarseGrainingKernel::overlap(),
                               CoarseGrainingKernel::gaussian(0.5), CoarseGrainingKernel::lucy(0.5)}) {
      const auto cg = coarseGrain(f, grid, kernel);
      double total = 0.0;
      for (double phi : cg.solidFraction) total += phi * grid.cellVolume();
      EXPECT_NEAR(total / (volume[0] + volume[1]), 1.0, 1e-12) << kernel.name() << " offset " << offset;
      ASSERT_EQ(cg.species.size(), 2u);
      EXPECT_EQ(cg.species[0].species, 3);
      EXPECT_EQ(cg.species[1].species, 7);
      bool passed = std::abs(total / (volume[0] + volume[1]) - 1.0) <= 1e-12;
      double worstSpecies = 0.0;
      for (int s = 0; s < 2; ++s) {
        double part = 0.0;
        for (double phi : cg.species[static_cast<std::size_t>(s)].solidFraction) part += phi * grid.cellVolume();
        EXPECT_NEAR(part / volume[s], 1.0, 1e-12) << kernel.name() << " species " << s;
        passed = passed && std::abs(part / volume[s] - 1.0) <= 1e-12;
        worstSpecies = std::max(worstSpecies, std::abs(part / volume[s] - 1.0));
      }
      grainbridge::testing::recordValidation(
          {grainbridge::testing::formatNote("extract.solid_fraction_integral.%s.le_offset%g", kernel.name().c_str(),
                                            offset),
           "Extraction (Section 2.3, Sections 6.3.2-6.3.3)",
           grainbridge::testing::formatNote("integral of the coarse-grained solid fraction (%s kernel, Lees-Edwards "
                                            "offset %g) against the total particle volume",
                                            kernel.name().c_str(), offset),
           "VALIDATION.md Extraction (Eq. 2.3 coarse graining)", volume[0] + volume[1], total, "round-off (1e-12)",
           passed,
           grainbridge::testing::formatNote("150 particles of two species on a periodic 6 x 5 x 4 grid; per species "
                                            "largest relative error %.1e",
                                            worstSpecies)});
    }
  }
}
