#include "engines/mfm/InitialBed.hpp"

#include "engines/closures/MinimumFluidization.hpp"
#include "engines/fluid/BedMeasures.hpp"

namespace grainbridge::mfm {

InitialInventory initialInventory(const MultiFluidSetup& setup, const InitialState& initial) {
  const auto& solids = setup.model.solids;
  const fluid::StaggeredGrid grid(setup.geometry);
  fluid::FlowState state(grid, 1 + solids.size());
  applyRegions(state, initial);
  const double bottom = fluid::bottomArea(setup.geometry, fluid::verticalAxis(setup.settings.gravity));
  InitialInventory inventory;
  for (std::size_t m = 1; m <= solids.size(); ++m) {
    const double v = fluid::solidsVolume(state, m);
    inventory.solidsVolume.push_back(v);
    inventory.buoyantWeight += v * (solids[m - 1].density - setup.model.gas.densityAt(initial.referencePressure)) *
                               setup.settings.gravity.norm() / bottom;
  }
  return inventory;
}

std::optional<double> dragMinimumFluidizationVelocity(const MultiFluidSetup& setup, const InitialState& initial) {
  const auto& solids = setup.model.solids;
  if (solids.empty()) return std::nullopt;
  for (const auto& region : initial.regions) {
    double solidsFraction = 0.0;
    for (double f : region.solidsFractions) solidsFraction += f;
    if (solidsFraction <= 0.0) continue;
    const closures::PackedBed bed{1.0 - solidsFraction,      solids[0].diameter,
                                  solids[0].density,         setup.model.gas.densityAt(initial.referencePressure),
                                  setup.model.gas.viscosity, setup.settings.gravity.norm()};
    return closures::minimumFluidizationVelocity(setup.model.drag, bed);
  }
  return std::nullopt;
}

}  // namespace grainbridge::mfm
