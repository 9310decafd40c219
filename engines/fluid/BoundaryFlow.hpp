#pragma once
// What a phase carries through each boundary patch: from its face mass fluxes (MassFlux.hpp, or
// the fluxes a step's closing continuity solve moved mass with), summed over the patch's faces,
// inflow and outflow apart (a pressure outlet may take some of its faces' flow back in). Walls
// carry nothing. The step's bookkeeping of a run that feeds or loses solids (Chapter 4's combine):
// held - held0 = in - out.
#include <array>
#include <vector>

#include "core/data/FieldFrame.hpp"
#include "engines/fluid/BedMeasures.hpp"
#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/Fields.hpp"

namespace grainbridge::fluid {

struct PatchFlow {
  double in = 0.0;   // into the domain, >= 0 [kg/s, or kg summed over steps]
  double out = 0.0;  // out of the domain, >= 0
};

// One entry per patch of `boundaries`, in their order, from F [kg/s] positive along each axis.
[[nodiscard]] std::vector<PatchFlow> patchFlows(const std::array<FaceField, 3>& flux, const Boundaries& boundaries);

// The sum over patches.
[[nodiscard]] PatchFlow total(const std::vector<PatchFlow>& patches);

// The superficial gas velocity U [m/s] the velocity inlets impose (Fig. 4.5's abscissa): the gas
// volume flow they let in, eps_g v_g A summed over the inlet patches (v_g the gas speed into the
// domain, normal to the patch's side; A the patch's area), over the cross-section normal to
// gravity (bottomArea). A pure-gas inlet over the whole bottom gives its speed exactly, its area
// over the bottom's being 1 exactly; a jet gives its speed times its share of the bottom. A
// pressure outlet's backflow is not counted: the flow is imposed by the inlets only.
// `patches` as an engine is built with (a whole side as from {0, 0}, to {-1, -1}, or resolved).
[[nodiscard]] double superficialGasVelocity(const std::vector<BoundaryPatch>& patches,
                                            const core::data::GridGeometry& geometry, VerticalAxis vertical);

// The mass of a phase the interior cells hold, sum rho eps dV [kg].
[[nodiscard]] double heldMass(const CellField& fraction, const CellField& density);

}  // namespace grainbridge::fluid
