// The minimum fluidization velocities the drag laws imply (VALIDATION.md, multi-fluid engine):
// the Goldschmidt bed's 1.21 m/s (Syamlal-O'Brien C 0.8 D 2.65; 2.49 mm, 2526 kg/m3, eps 0.417)
// and 0.87 m/s for its 1.52 mm particles; the Ergun branch 1.32 and 0.92 m/s.
#include <gtest/gtest.h>

#include "engines/closures/MinimumFluidization.hpp"

using namespace grainbridge::closures;

namespace {

PackedBed goldschmidt(double d) { return PackedBed{0.417, d, 2526.0, 1.2, 1.8e-5, 9.81}; }

}  // namespace

TEST(MinimumFluidization, SyamlalOBrienGivesTheGoldschmidtValues) {
  const auto drag = GasSolidsDrag::byName("syamlal_obrien");
  EXPECT_NEAR(minimumFluidizationVelocity(drag, goldschmidt(2.49e-3)), 1.21, 0.005);
  EXPECT_NEAR(minimumFluidizationVelocity(drag, goldschmidt(1.52e-3)), 0.87, 0.005);
}

TEST(MinimumFluidization, ErgunBranchGivesTheGoldschmidtValues) {
  const auto drag = GasSolidsDrag::byName("ergun_wen_yu");
  EXPECT_NEAR(minimumFluidizationVelocity(drag, goldschmidt(2.49e-3)), 1.32, 0.005);
  EXPECT_NEAR(minimumFluidizationVelocity(drag, goldschmidt(1.52e-3)), 0.92, 0.005);
}

TEST(MinimumFluidization, AtItTheDragCarriesTheBedsBuoyantWeight) {
  const auto drag = GasSolidsDrag::byName("syamlal_obrien");
  const PackedBed bed{0.404, 2.3e-3, 1491.8, 1.2, 1.8e-5, 9.81};
  const double U = minimumFluidizationVelocity(drag, bed);
  const DragState s{0.404, 0.596, 2.3e-3, 1.2, 1.8e-5, U / 0.404};
  // beta U / eps_g^2 per unit height against eps_s (rho_s - rho_g) g.
  EXPECT_NEAR(drag.evaluate(s).beta * U / (0.404 * 0.404), 0.596 * (1491.8 - 1.2) * 9.81, 1e-6);
}
