// What a fluidization curve is read against, from the set-up alone (engines/mfm/InitialBed): the
// inventory equals, bit for bit, the one measured on a freshly initialised engine (what the mfm
// stage weighed before), the weight is the packed bed's (1 - eps) (rho_s - rho_g) g H, and U_mf
// is the drag law's at the bed region's void fraction, the freeboard region (no solids) skipped.
#include "engines/mfm/InitialBed.hpp"

#include <gtest/gtest.h>

#include <utility>

#include "engines/closures/MinimumFluidization.hpp"
#include "engines/fluid/BedMeasures.hpp"
#include "tests/engines/mfm/GrainBed.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;

TEST(InitialBed, InventoryEqualsAFreshEnginesBitForBit) {
  GrainBedSpec spec;
  spec.nx = 4;
  spec.perturbation = 0.02;
  const GrainBed bed = grainBed(spec);
  mfm::MultiFluidEngine fresh(bed.setup.geometry, bed.setup.patches, bed.setup.model, bed.setup.settings,
                              bed.setup.limits);
  mfm::initialise(fresh, bed.initial);
  const mfm::InitialInventory inventory = mfm::initialInventory(bed.setup, bed.initial);
  ASSERT_EQ(inventory.solidsVolume.size(), 1u);
  EXPECT_EQ(inventory.solidsVolume[0], fluid::solidsVolume(fresh.state(), 1));
  // Unperturbed: the packed bed's weight per unit bottom area, bedCells rows high.
  spec.perturbation = 0.0;
  const GrainBed packed = grainBed(spec);
  const double height = spec.bedCells * spec.cell;
  const double rhoGas = packed.setup.model.gas.densityAt(packed.initial.referencePressure);
  EXPECT_NEAR(mfm::initialInventory(packed.setup, packed.initial).buoyantWeight,
              (1.0 - spec.voidFraction) * (kGrainDensity - rhoGas) * kGravity * height, 1e-9);
}

TEST(InitialBed, DragMinimumFluidizationIsTheFirstSolidsRegions) {
  const GrainBed bed = grainBed(GrainBedSpec{});
  const auto umf = mfm::dragMinimumFluidizationVelocity(bed.setup, bed.initial);
  ASSERT_TRUE(umf.has_value());
  // The region's void fraction as the function forms it, from its solids fraction.
  const closures::PackedBed packed{1.0 - (1.0 - GrainBedSpec{}.voidFraction),
                                   kGrainDiameter,
                                   kGrainDensity,
                                   bed.setup.model.gas.densityAt(bed.initial.referencePressure),
                                   bed.setup.model.gas.viscosity,
                                   kGravity};
  EXPECT_EQ(*umf, closures::minimumFluidizationVelocity(bed.setup.model.drag, packed));
  mfm::InitialState freeboardFirst = bed.initial;
  std::swap(freeboardFirst.regions[0], freeboardFirst.regions[1]);
  EXPECT_EQ(mfm::dragMinimumFluidizationVelocity(bed.setup, freeboardFirst), umf);
  mfm::InitialState noSolids = bed.initial;
  for (auto& region : noSolids.regions)
    for (auto& f : region.solidsFractions) f = 0.0;
  EXPECT_FALSE(mfm::dragMinimumFluidizationVelocity(bed.setup, noSolids).has_value());
}
