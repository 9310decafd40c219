#include "engines/fluid/MassFlux.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

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
                                    const OutflowBudget& budget, std::size_t m) {
  const StaggeredGrid& grid = boundaries.grid();
  const CellField& fraction = phase.fraction;
  const auto upwindOf = [&](int a, std::size_t f, double u) { return u >= 0.0 ? f : grid.neighbour(f, a, +1); };
  // First superbee's face values, held in the flux fields; with a budget, each interior cell's
  // antidiffusive outflow rate (the face value beyond the upwind cell's own).
  std::array<FaceField, 3> flux{FaceField(grid, 0), FaceField(grid, 1), FaceField(grid, 2)};
  for (int a = 0; a < grid.dimensions(); ++a) {
    const FaceField& v = phase.velocity[static_cast<std::size_t>(a)];
    FaceField& face = flux[static_cast<std::size_t>(a)];
    for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
      if (!boundaries.openFace(a, f)) continue;
      face[f] = faceFraction(fraction, a, f, v[f]);
      int inward = 0;
      if (m > 0) {
        if (const BoundaryPatch* outlet = boundaries.outletOfFace(a, f, inward); outlet && v[f] * inward > 0.0)
          face[f] = outlet->phases[m].fraction;
      }
    }
  }
  std::optional<CellField> antidiffusiveOut;
  if (budget.start != nullptr) {
    antidiffusiveOut.emplace(grid, 0.0);
    for (int a = 0; a < grid.dimensions(); ++a) {
      const FaceField& v = phase.velocity[static_cast<std::size_t>(a)];
      const FaceField& face = flux[static_cast<std::size_t>(a)];
      for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
        if (!boundaries.openFace(a, f)) continue;
        const std::size_t upwind = upwindOf(a, f, v[f]);
        const double extra = face[f] - std::max(fraction[upwind], 0.0);
        if (extra > 0.0) (*antidiffusiveOut)[upwind] += std::abs(v[f]) * grid.faceArea(a) * extra;
      }
    }
  }
  // Then each face value, limited where its upwind cell's budget requires, becomes its flux.
  for (int a = 0; a < grid.dimensions(); ++a) {
    const FaceField& v = phase.velocity[static_cast<std::size_t>(a)];
    FaceField& F = flux[static_cast<std::size_t>(a)];
    const double area = grid.faceArea(a);
    for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
      if (!boundaries.openFace(a, f)) continue;
      const double u = v[f];
      const std::size_t upwind = upwindOf(a, f, u);
      double face = F[f];
      if (antidiffusiveOut && grid.interior(upwind)) {
        const double held = std::max((*budget.start)[upwind], 0.0) * grid.cellVolume() / budget.dt;
        const double upwindValue = std::max(fraction[upwind], 0.0);
        const double out = (*antidiffusiveOut)[upwind];
        if (face > upwindValue && out > held) face = upwindValue + (face - upwindValue) * (held / out);
      }
      F[f] = density[upwind] * face * u * area;
    }
  }
  return flux;
}

}  // namespace grainbridge::fluid
