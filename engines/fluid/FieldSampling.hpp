#pragma once
// The flow read where a coupled particle engine (TF-DEM, Section 7.2.3) needs it: a phase's
// velocity at a cell centre or at any point, and the gas pressure gradient of a cell (the
// -V_p grad P_g of Eq. 7.28). The staggered components are interpolated linearly along each axis
// between the faces, or the cell centres, that carry them; ghosts take part, so after
// Boundaries::apply a point next to a no-slip wall sees the wall's zero tangential velocity.
#include <cstddef>

#include "core/Types.hpp"
#include "engines/fluid/FlowState.hpp"

namespace grainbridge::fluid {

// The mean of the two faces of the cell along each axis (zero along z in 2D) [m/s].
[[nodiscard]] Vec3 cellVelocity(const PhaseFields& phase, std::size_t cell);

// Each component interpolated linearly in every active axis; a point outside the domain takes the
// value at the nearest point inside it [m/s].
[[nodiscard]] Vec3 velocityAt(const PhaseFields& phase, const Vec3& point);

// Central differences of the interior neighbours, one-sided beside a boundary (a ghost's pressure
// is a boundary condition's, not a value of the flow there), zero along an axis of one cell and
// along z in 2D [Pa/m].
[[nodiscard]] Vec3 pressureGradient(const CellField& pressure, std::size_t cell);

}  // namespace grainbridge::fluid
