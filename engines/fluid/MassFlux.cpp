#include "engines/fluid/MassFlux.hpp"

#include <algorithm>

#include "engines/fluid/SuperbeeOnGrid.hpp"

namespace grainbridge::fluid {

namespace {

double superbeeFraction(const CellField& fraction, int axis, std::size_t face, double u) {
  const StaggeredGrid& grid = fraction.grid();
  const int position = grid.coordinates(face)[static_cast<std::size_t>(axis)];
  if (position >= grid.cells(axis)) return fraction[face];  // past the last ghost: nothing downstream
  return superbeeOnGrid(grid, fraction, face, axis, position, u);
}

}  // namespace

double faceFraction(const CellField& fraction, int axis, std::size_t face, double u) {
  // Never a negative face fraction: a cell that round-off or the deferred correction left a
  // hair below zero must not export negative mass (which would draw it further down). The
  // limit acts on the face value both cells share, so mass stays conserved.
  return std::max(superbeeFraction(fraction, axis, face, u), 0.0);
}

std::array<FaceField, 3> massFluxes(const PhaseFields& phase, const CellField& density, const Boundaries& boundaries,
                                    const OutflowBudget& budget) {
  const StaggeredGrid& grid = boundaries.grid();
  const CellField& fraction = phase.fraction;
  // Each face's upwind cell, and superbee's face value split into the upwind cell's value and
  // the antidiffusive rest; with a budget, each interior cell's antidiffusive outflow rate.
  std::array<FaceField, 3> value{FaceField(grid, 0), FaceField(grid, 1), FaceField(grid, 2)};
  CellField antidiffusiveOut(grid, 0.0);
  for (int a = 0; a < grid.dimensions(); ++a) {
    const FaceField& v = phase.velocity[static_cast<std::size_t>(a)];
    for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
      if (!boundaries.openFace(a, f)) continue;
      value[static_cast<std::size_t>(a)][f] = faceFraction(fraction, a, f, v[f]);
      if (budget.start == nullptr) continue;
      const std::size_t upwind = v[f] >= 0.0 ? f : grid.neighbour(f, a, +1);
      const double extra = value[static_cast<std::size_t>(a)][f] - std::max(fraction[upwind], 0.0);
      if (extra > 0.0) antidiffusiveOut[upwind] += std::abs(v[f]) * grid.faceArea(a) * extra;
    }
  }
  std::array<FaceField, 3> flux{FaceField(grid, 0), FaceField(grid, 1), FaceField(grid, 2)};
  for (int a = 0; a < grid.dimensions(); ++a) {
    const FaceField& v = phase.velocity[static_cast<std::size_t>(a)];
    FaceField& F = flux[static_cast<std::size_t>(a)];
    const double area = grid.faceArea(a);
    for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
      if (!boundaries.openFace(a, f)) continue;
      const double u = v[f];
      const std::size_t upwind = u >= 0.0 ? f : grid.neighbour(f, a, +1);
      double face = value[static_cast<std::size_t>(a)][f];
      if (budget.start != nullptr && grid.interior(upwind)) {
        const double held = std::max((*budget.start)[upwind], 0.0) * grid.cellVolume() / budget.dt;
        const double upwindValue = std::max(fraction[upwind], 0.0);
        if (face > upwindValue && antidiffusiveOut[upwind] > held)
          face = upwindValue + (face - upwindValue) * (held / antidiffusiveOut[upwind]);
      }
      F[f] = density[upwind] * face * u * area;
    }
  }
  return flux;
}

}  // namespace grainbridge::fluid
