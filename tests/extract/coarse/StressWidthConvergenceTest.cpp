// Section 8.2.1.3: stress against the coarse-graining width w. In a homogeneous state (a
// periodic DEM gas) the stress field of every width averages over the box to the whole-domain
// value (to round-off: each kernel deposits every particle and contact exactly once), and its
// spread about that value shrinks as w grows, so the field converges to the whole-domain stress.
#include <gtest/gtest.h>

#include <cmath>

#include "extract/coarse/CoarseGrain.hpp"
#include "extract/coarse/DomainAverages.hpp"
#include "tests/engines/dem/DemTestSupport.hpp"

using namespace grainbridge;
using namespace grainbridge::dem::testing;
namespace coarse = grainbridge::extract::coarse;

TEST(StressWidthConvergence, FieldConvergesToTheWholeDomainStressAsTheWidthGrows) {
  Gas g = periodicGas(500, 0.3, 1.0, table61Particle(), 2e-4, 9);
  dem::Simulation sim(g.setup, g.particles);
  sim.run(300);
  sim.step(true);
  const auto f = sim.frame();
  ASSERT_GT(f.contacts.size(), 10u);
  const auto whole = coarse::averageWholeDomain(f);
  const core::grid::CellGrid grid(f.domain.lo, f.domain.hi, {8, 8, 8}, {true, true, true});
  const double d = 1.0;
  for (auto kind : {coarse::KernelKind::Gaussian, coarse::KernelKind::Lucy}) {
    double previous = INFINITY;
    for (double w : {0.5 * d, 1.0 * d, 2.0 * d, 3.0 * d}) {  // Gaussian cutoff up to 0.8 box
      const auto cg = coarse::coarseGrain(f, grid, {kind, w});
      // Domain mean of the contact stress is the whole-domain value; the kinetic part is taken
      // about local means, so compare the pressure spread of the total.
      Mat3 mean = Mat3::Zero();
      double spread = 0.0;
      for (const Mat3& s : cg.contactStress) mean += s / static_cast<double>(grid.cellCount());
      EXPECT_LT((mean - whole.contactStress).norm(), 1e-12 * whole.contactStress.norm());
      for (double p : cg.pressure) spread += (p - whole.pressure) * (p - whole.pressure);
      spread = std::sqrt(spread / static_cast<double>(grid.cellCount())) / whole.pressure;
      std::printf("%s w = %.1f d: rms (p - p_domain) / p_domain = %.3f, times (w/d)^1.5 = %.3f\n",
                  cg.kernel.name().c_str(), w, spread, spread * std::pow(w / d, 1.5));
      EXPECT_LT(spread, 0.75 * previous);  // noise falls about as w^(-3/2)
      previous = spread;
    }
    EXPECT_LT(previous, 0.15);
  }
}
