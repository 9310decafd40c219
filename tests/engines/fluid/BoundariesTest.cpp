// Ghost-cell boundary rules (Section 3.3.2.2): a jet through part of the bottom sets the inflow
// on its faces only, walls hold the normal velocity at zero and mirror the tangential one
// (no-slip: the wall value, the mean of ghost and interior, is zero; free slip: no gradient),
// an outlet gives each phase the interior's fraction while it leaves; bad patches are refused.
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/MassFlux.hpp"

using namespace grainbridge;
using namespace grainbridge::fluid;

namespace {

StaggeredGrid grid8x4() {
  core::data::GridGeometry g;
  g.cells = {8, 4, 1};
  g.spacing = Vec3(0.01, 0.01, 0.01);
  return StaggeredGrid(g);
}

BoundaryPatch jet() {
  BoundaryPatch p;
  p.kind = BoundaryKind::VelocityInlet;
  p.side = YLow;
  p.from = {3, 0};
  p.to = {5, 1};
  p.phases = {PhaseInflow{0.9, Vec3(0.0, 40.0, 0.0)}, PhaseInflow{0.1, Vec3(0.0, 2.0, 0.0)}};
  return p;
}

}  // namespace

TEST(Boundaries, AJetSetsItsFacesOnlyAndWallsMirrorTheTangentialVelocity) {
  const StaggeredGrid grid = grid8x4();
  BoundaryPatch freeSlip;
  freeSlip.kind = BoundaryKind::FreeSlipWall;
  freeSlip.side = XLow;
  const Boundaries b(grid, {jet(), freeSlip}, 2);
  FlowState st(grid, 2);
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    st.phases[0].velocity[0][c] = 1.0;  // a tangential gas velocity along x everywhere
    st.phases[0].velocity[1][c] = 3.0;
  }
  b.apply(st);
  for (int i = 0; i < 8; ++i) {
    const bool inJet = i >= 3 && i < 5;
    // The bottom face of cell (i, 0) is stored at the ghost (i, -1).
    EXPECT_EQ(st.phases[0].velocity[1](i, -1, 0), inJet ? 40.0 : 0.0) << i;
    EXPECT_EQ(st.phases[1].velocity[1](i, -1, 0), inJet ? 2.0 : 0.0) << i;
    EXPECT_EQ(st.phases[1].fraction(i, -1, 0), inJet ? 0.1 : 0.0) << i;
    // Tangential u_x in the bottom ghost row: the inlet's 0 on the face means ghost = -interior,
    // as on the no-slip wall beside it. (i = 7 is the x-high wall's face, where u_x is 0.)
    if (i < 7) {
      EXPECT_EQ(st.phases[0].velocity[0](i, -1, 0), -1.0) << i;
    }
  }
  // The free-slip wall at x low: tangential v_y copied, normal u_x zero on the wall face.
  EXPECT_EQ(st.phases[0].velocity[1](-1, 2, 0), st.phases[0].velocity[1](0, 2, 0));
  EXPECT_EQ(st.phases[0].velocity[0](-1, 2, 0), 0.0);
  // Only the jet's two faces and no wall face let mass through along y at the bottom.
  int open = 0;
  for (int i = 0; i < 8; ++i) open += b.openFace(1, grid.index(i, -1, 0)) ? 1 : 0;
  EXPECT_EQ(open, 2);
}

TEST(Boundaries, AnOutletTakesEachPhasesOwnDirection) {
  const StaggeredGrid grid = grid8x4();
  BoundaryPatch outlet;
  outlet.kind = BoundaryKind::PressureOutlet;
  outlet.side = YHigh;
  outlet.pressure = 5.0;
  const Boundaries b(grid, {outlet}, 2);
  FlowState st(grid, 2);
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    st.phases[0].fraction[c] = 0.7;
    st.phases[1].fraction[c] = 0.3;
    st.phases[0].velocity[1][c] = 1.0;   // gas leaving
    st.phases[1].velocity[1][c] = -1.0;  // solids falling back in
  }
  b.apply(st);
  EXPECT_EQ(st.pressure(2, 4, 0), 5.0);
  EXPECT_EQ(st.phases[0].fraction(2, 4, 0), 0.7);  // the gas leaving: the interior's
  // A solids phase's ghost repeats the interior either way (the face's coefficients stay
  // continuous when it turns); what it brings back in is the backflow state's: none.
  EXPECT_EQ(st.phases[1].fraction(2, 4, 0), 0.3);
  const std::size_t face = grid.index(2, 3, 0);
  const CellField density(grid, 1.0);
  EXPECT_EQ(massFluxes(st.phases[1], density, b, {}, 1)[1][face], 0.0);
  EXPECT_DOUBLE_EQ(massFluxes(st.phases[0], density, b)[1][face], 0.7 * grid.faceArea(1));
  st.phases[1].velocity[1][face] = 1.0;  // leaving: the interior's fraction goes out
  EXPECT_DOUBLE_EQ(massFluxes(st.phases[1], density, b, {}, 1)[1][face], 0.3 * grid.faceArea(1));
  EXPECT_TRUE(b.solvedFace(1, grid.index(2, 3, 0)));  // the outlet face is solved
}

TEST(Boundaries, OverlappingOrOffSidePatchesAreRefused) {
  const StaggeredGrid grid = grid8x4();
  BoundaryPatch wide = jet();
  wide.to = {9, 1};
  EXPECT_THROW(Boundaries(grid, {wide}, 2), Error);
  BoundaryPatch z = jet();
  z.side = ZLow;
  EXPECT_THROW(Boundaries(grid, {z}, 2), Error);
  EXPECT_THROW(Boundaries(grid, {jet(), jet()}, 2), Error);
  BoundaryPatch fewPhases = jet();
  fewPhases.phases.pop_back();
  EXPECT_THROW(Boundaries(grid, {fewPhases}, 2), Error);
}

// The granular temperature an inflow carries (issue 29): a jet that states it puts it in its
// ghosts, which the granular-energy equation convects and conducts in; without it, and on the
// rest of the side, the ghost repeats the interior (zero gradient).
TEST(Boundaries, AnInletStatesTheGranularTemperatureItsInflowCarries) {
  const StaggeredGrid grid = grid8x4();
  BoundaryPatch stated = jet();
  stated.phases[1].granularTemperature = 0.25;
  for (const bool given : {true, false}) {
    const Boundaries b(grid, {given ? stated : jet()}, 2);
    FlowState st(grid, 2);
    for (std::size_t c = 0; c < grid.paddedCount(); ++c) st.phases[1].granularTemperature[c] = 0.01;
    b.apply(st);
    for (int i = 0; i < 8; ++i) {
      const bool onJet = i >= 3 && i < 5;
      EXPECT_EQ(st.phases[1].granularTemperature(i, -1, 0), given && onJet ? 0.25 : 0.01) << "cell " << i;
    }
  }
}
