// Above minimum fluidization the gas carries the bed: its time-averaged pressure drop equals the
// bed's weight per unit area, (1 - eps)(rho_s - rho_g) g H (the red line of Fig. 4.5), and the
// solids mass in a bed that nothing leaves stays what it was.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/engines/mfm/GrainBed.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;

namespace {

// Solids volume in the domain per unit depth [m^2].
double solidsVolume(const mfm::MultiFluidEngine& bed) {
  const auto& grid = bed.grid();
  double v = 0.0;
  for (int j = 0; j < grid.cells(1); ++j)
    for (int i = 0; i < grid.cells(0); ++i)
      v += bed.state().phases[1].fraction(i, j, 0) * grid.spacing(0) * grid.spacing(1);
  return v;
}

// The gas pressure on the inlet face (extrapolated from the two bottom rows) less that at the top
// row's centre, averaged across the bed's width.
double bedPressureDrop(const mfm::MultiFluidEngine& bed) {
  const auto& grid = bed.grid();
  const auto& p = bed.state().pressure;
  const int nx = grid.cells(0), top = grid.cells(1) - 1;
  double dp = 0.0;
  for (int i = 0; i < nx; ++i) dp += 1.5 * p(i, 0, 0) - 0.5 * p(i, 1, 0) - p(i, top, 0);
  return dp / nx;
}

}  // namespace

TEST(FluidizedBed, TimeAveragedPressureDropCarriesTheBedsWeight) {
  GrainBedSpec spec;
  spec.nx = 4;
  spec.inflow = 1.2;  // 1.5 U_mf
  spec.perturbation = 0.02;
  auto bed = makeGrainBed(spec);
  const auto& grid = bed->grid();
  const double width = grid.cells(0) * grid.spacing(0);
  // The solids' weight less its buoyancy, and the gas column's weight, per unit area.
  const double solids = solidsVolume(*bed) / width * (kGrainDensity - kAirDensity) * kGravity;
  const double gasColumn = kAirDensity * kGravity * (grid.cells(1) - 0.5) * grid.spacing(1);
  bed->advanceTo(0.5);
  // The time integral of the drop over every step of the window, as the implicit steps apply it
  // (sampling at fixed times would weigh the short spikes of a collapsing void by chance).
  double integral = 0.0, window = 0.0;
  while (bed->time() < 2.5 - 1e-12) {
    bed->step(2.5);
    integral += bed->statistics().lastDt * bedPressureDrop(*bed);
    window += bed->statistics().lastDt;
  }
  const double measured = integral / window - gasColumn;
  std::printf(
      "fluidized bed at U = %.2f m/s: mean dp %.1f Pa against the bed weight %.1f Pa; %ld steps, %ld "
      "retries, %.1f iterations per step\n",
      spec.inflow, measured, solids, bed->statistics().steps, bed->statistics().retries,
      double(bed->statistics().iterations) / double(bed->statistics().steps));
  EXPECT_NEAR(measured, solids, 0.03 * solids);
}

TEST(FluidizedBed, SolidsMassIsConservedInAWalledBed) {
  GrainBedSpec spec;
  spec.nx = 4;
  spec.inflow = 1.2;
  spec.perturbation = 0.02;
  auto bed = makeGrainBed(spec);
  const double before = solidsVolume(*bed);
  bed->advanceTo(0.5);
  const double after = solidsVolume(*bed);
  std::printf("solids volume %.12e -> %.12e (relative change %.2e)\n", before, after, (after - before) / before);
  EXPECT_NEAR(after, before, 1e-6 * before);
}
