// A binary grain bed (issue 26) in the engine: a loose mixed bed settling without gas inflow
// packs on its total solids fraction (Eq. 3.68), never beyond eps_s,max + 0.01, and each phase
// keeps its mass to 1e-10 of its inventory over 1 s (walls at the sides, the bottom closed to the
// solids, the top a gas outlet the solids never reach).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engines/fluid/BedMeasures.hpp"
#include "tests/engines/mfm/GrainBed.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;

TEST(BinaryBed, ASettlingMixturePacksOnItsTotalFractionAndKeepsEachPhase) {
  GrainBedSpec spec;
  spec.nx = 4;
  spec.inflow = 0.0;
  spec.voidFraction = 0.5;  // loose: 0.25 + 0.25 under eps_s,max 0.596
  GrainBed bed = binaryGrainBed(spec);
  // Eq. 3.68's omega 1, as the Goldschmidt configs run: omega < 1 withholds part of each packed
  // cell's correction and lets a step converge with up to 1e-10 of the inventory withheld
  // (docs/multi-fluid.md), which over a settling second's hundreds of steps adds up past 1e-10.
  bed.setup.settings.fractionRelaxation = 1.0;
  const auto& e = bed.setup;
  mfm::MultiFluidEngine engine(e.geometry, e.patches, e.model, e.settings, e.limits);
  mfm::initialise(engine, bed.initial);
  const double small0 = fluid::solidsVolume(engine.state(), 1), large0 = fluid::solidsVolume(engine.state(), 2);
  const double packed = e.settings.packedFraction;
  double densest = 0.0;
  for (int k = 1; k <= 20; ++k) {
    engine.advanceTo(0.05 * k);
    const auto& state = engine.state();
    const auto& grid = state.grid();
    for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
      if (!grid.interior(c)) continue;
      densest = std::max(densest, state.phases[1].fraction[c] + state.phases[2].fraction[c]);
    }
    EXPECT_NEAR(fluid::solidsVolume(state, 1), small0, 1e-10 * small0) << "t = " << state.time;
    EXPECT_NEAR(fluid::solidsVolume(state, 2), large0, 1e-10 * large0) << "t = " << state.time;
  }
  EXPECT_LE(densest, packed + 0.01);
  EXPECT_GT(densest, 0.5 + 0.02);  // it did settle: the bottom packed beyond the start
}
