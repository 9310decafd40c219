#pragma once
// What a phase carries through each boundary patch: from its face mass fluxes (MassFlux.hpp, or
// the fluxes a step's closing continuity solve moved mass with), summed over the patch's faces,
// inflow and outflow apart (a pressure outlet may take some of its faces' flow back in). Walls
// carry nothing. The step's bookkeeping of a run that feeds or loses solids (Chapter 4's combine):
// held - held0 = in - out.
#include <array>
#include <vector>

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

// The mass of a phase the interior cells hold, sum rho eps dV [kg].
[[nodiscard]] double heldMass(const CellField& fraction, const CellField& density);

}  // namespace grainbridge::fluid
