#include "engines/fluid/ConvectionDiffusion.hpp"

#include <algorithm>

#include "engines/fluid/SuperbeeOnGrid.hpp"

namespace grainbridge::fluid {

namespace {

// Superbee minus upwind value at the high face of cell c along `axis` (velocity u there), c at
// `position` along it.
double correctionAt(const StaggeredGrid& grid, const CellField& phi, std::size_t c, int axis, int position, double u) {
  return superbeeOnGrid(grid, phi, c, axis, position, u) - upwindOnGrid(grid, phi, c, axis, u);
}

}  // namespace

StencilSystem assembleConvectionDiffusion(const ConvectionDiffusion& eq, const CellField& phi) {
  const StaggeredGrid& grid = phi.grid();
  StencilSystem system(grid);
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::array<int, 3> at{i, j, k};
        const std::size_t c = grid.index(i, j, k);
        double sumNb = 0.0, netOutflow = 0.0, correction = 0.0;
        for (int axis = 0; axis < grid.dimensions(); ++axis) {
          const double area = grid.faceArea(axis);
          const double D = eq.diffusivity * area / grid.spacing(axis);
          const FaceField* v = eq.velocity[static_cast<std::size_t>(axis)];
          const std::size_t low = grid.neighbour(c, axis, -1);
          // Mass fluxes through the high face of c and of its low neighbour (c's low face).
          const double uHigh = v != nullptr ? (*v)[c] : 0.0;
          const double uLow = v != nullptr ? (*v)[low] : 0.0;
          const double Fe = eq.density * uHigh * area, Fw = eq.density * uLow * area;
          const double aHigh = D + std::max(-Fe, 0.0), aLow = D + std::max(Fw, 0.0);
          system.anb(c, 2 * axis + 1) = aHigh;
          system.anb(c, 2 * axis) = aLow;
          sumNb += aHigh + aLow;
          netOutflow += Fe - Fw;
          // Deferred correction: F (Phi_superbee - Phi_upwind) out through the high face, in
          // through the low face.
          correction += Fe * correctionAt(grid, phi, c, axis, at[static_cast<std::size_t>(axis)], uHigh) -
                        Fw * correctionAt(grid, phi, low, axis, at[static_cast<std::size_t>(axis)] - 1, uLow);
        }
        system.ap(c) = sumNb + netOutflow;
        system.b(c) = eq.source * grid.cellVolume() - correction;
      }
    }
  }
  return system;
}

}  // namespace grainbridge::fluid
