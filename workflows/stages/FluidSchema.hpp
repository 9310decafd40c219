#pragma once
// The gas keys the stages on engines/fluid share (`mfm`, and `tfdem` with particles in the gas):
// a boundary patch (fluid::FluidSetup's patches as the user writes them) and a pressure tap.
#include <memory>

#include "workflows/params/ParamSchema.hpp"

namespace grainbridge::workflows::stages {

// One boundary patch: side, kind, from/to, gas_inflow, solids_fractions, solids_inflow, pressure.
std::shared_ptr<const params::ParamSchema> boundarySchema();
// One pressure tap: name, low, high (heights above the bottom).
std::shared_ptr<const params::ParamSchema> tapSchema();

}  // namespace grainbridge::workflows::stages
