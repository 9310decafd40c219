#pragma once
// Eq. 3.60 along a grid line: the superbee value on the face between padded entries p and
// p + e_axis of a field (a cell scalar, or a velocity component on its own faces), for the flow
// u through that face. Superbee reads the value beyond the upwind one; where that lies past the
// ghost layer (padded positions run from -1 to n along an axis) the face takes the upwind value.
// The continuity fluxes, the scalar transport and the momentum convection all use this one rule.
#include <cstddef>

#include "engines/fluid/StaggeredGrid.hpp"
#include "engines/fluid/Superbee.hpp"

namespace grainbridge::fluid {

// `position` is p's index along `axis`.
template <class Values>
[[nodiscard]] double superbeeOnGrid(const StaggeredGrid& grid, const Values& phi, std::size_t p, int axis, int position,
                                    double u) {
  const std::size_t e = grid.neighbour(p, axis, +1);
  if (u >= 0.0) {
    if (position - 1 < -1) return phi[p];
    return superbeeFaceValue(u, phi[grid.neighbour(p, axis, -1)], phi[p], phi[e], phi[e]);
  }
  if (position + 2 > grid.cells(axis)) return phi[e];
  return superbeeFaceValue(u, phi[p], phi[p], phi[e], phi[grid.neighbour(e, axis, +1)]);
}

// The same face's upwind value: what the matrix of a deferred correction carries.
template <class Values>
[[nodiscard]] double upwindOnGrid(const StaggeredGrid& grid, const Values& phi, std::size_t p, int axis, double u) {
  return u >= 0.0 ? phi[p] : phi[grid.neighbour(p, axis, +1)];
}

}  // namespace grainbridge::fluid
