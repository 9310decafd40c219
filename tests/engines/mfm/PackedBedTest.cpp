// Below minimum fluidization the grains stay put and the gas seeps through them: the pressure
// drop across the bed is the drag law's, -dP/dy = F_gm(eps_g, U / eps_g) U / eps_g^2 + rho_g g
// (the gas momentum balance of Eq. 3.3 with v_s = 0 and the gas at U / eps_g by continuity),
// which is what the reference calibrated C and D against (Fig. 4.5).
#include <gtest/gtest.h>

#include <cmath>

#include "engines/closures/SyamlalOBrien.hpp"
#include "tests/engines/mfm/GrainBed.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;

namespace {

void expectDragLawPressureDrop(const GrainBedSpec& spec) {
  auto bed = makeGrainBed(spec);
  bed->advanceTo(0.3);
  const auto& st = bed->state();
  const auto& grid = bed->grid();
  closures::SyamlalOBrien law;
  law.params = {spec.c, spec.d};
  // Between the centres of rows 1 and 6, inside the bed, column 0.
  double expected = 0.0, fastestSolids = 0.0;
  for (int j = 1; j < 6; ++j) {
    const std::size_t f = grid.index(0, j, 0);  // the face between rows j and j + 1
    const double epsG = 0.5 * (st.phases[0].fraction(0, j, 0) + st.phases[0].fraction(0, j + 1, 0));
    const double v = spec.inflow / epsG;
    const closures::DragState ds{epsG, 1.0 - epsG, kGrainDiameter, kAirDensity, kAirViscosity, v};
    expected += spec.cell * (law.evaluate(ds).beta * v / epsG + kAirDensity * kGravity);
    fastestSolids = std::max(fastestSolids, std::abs(st.phases[1].velocity[1][f]));
  }
  const double measured = st.pressure(0, 1, 0) - st.pressure(0, 6, 0);
  std::printf("packed bed (%dD) at U = %.2f m/s: dp = %.2f Pa against the drag law's %.2f Pa; %ld steps, %ld retries\n",
              grid.dimensions(), spec.inflow, measured, expected, bed->statistics().steps, bed->statistics().retries);
  EXPECT_NEAR(measured, expected, 0.02 * expected);
  EXPECT_LT(fastestSolids, 1e-3);  // the grains stay put
}

}  // namespace

TEST(PackedBed, PressureDropFollowsTheDragLawBelowMinimumFluidization) {
  GrainBedSpec spec;
  spec.inflow = 0.4;  // half of U_mf (about 0.80 m/s for C 0.8, D 2.65)
  expectDragLawPressureDrop(spec);
}

TEST(PackedBed, SoDoesItOnAThreeDimensionalGrid) {
  GrainBedSpec spec;
  spec.nz = 2;
  spec.inflow = 0.4;
  expectDragLawPressureDrop(spec);
}

TEST(PackedBed, AndOnASingleColumnOfCells) {
  // One cell across: the x momentum has no unknown face (both are walls), which the sparse solve
  // must take in its stride (Eigen's LU divides by zero on an empty matrix).
  GrainBedSpec spec;
  spec.nx = 1;
  spec.inflow = 0.4;
  expectDragLawPressureDrop(spec);
}
