#include "engines/mfm/GranularEnergy.hpp"

#include <algorithm>

#include "engines/fluid/SuperbeeOnGrid.hpp"

namespace grainbridge::mfm {

namespace {

bool isWall(fluid::BoundaryKind kind) {
  return kind == fluid::BoundaryKind::NoSlipWall || kind == fluid::BoundaryKind::FreeSlipWall;
}

// Superbee minus upwind theta on the high face of cell c along `axis` for the mass flux F there.
double correctionAt(const fluid::StaggeredGrid& grid, const fluid::CellField& theta, std::size_t c, int axis,
                    int position, double F) {
  return fluid::superbeeOnGrid(grid, theta, c, axis, position, F) - fluid::upwindOnGrid(grid, theta, c, axis, F);
}

double harmonicMean(double a, double b) { return a > 0.0 && b > 0.0 ? 2.0 * a * b / (a + b) : 0.0; }

}  // namespace

fluid::StencilSystem assembleGranularEnergy(const GranularEnergyInputs& in, std::size_t m,
                                            const std::array<fluid::FaceField, 3>& massFlux,
                                            const GranularEnergyTerms& terms) {
  const fluid::FlowState& state = *in.state;
  const fluid::StaggeredGrid& grid = state.grid();
  const fluid::PhaseFields& phase = state.phases[m];
  const fluid::CellField& theta = phase.granularTemperature;
  const fluid::Boundaries& boundaries = *in.boundaries;
  const double V = grid.cellVolume();
  fluid::StencilSystem system(grid);
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::array<int, 3> at{i, j, k};
        const std::size_t c = grid.index(i, j, k);
        if (phase.fraction[c] < in.diluteFraction) {
          // The mean of the neighbours that hold solids; none: zero (no grains, no fluctuation).
          double count = 0.0;
          for (int axis = 0; axis < grid.dimensions(); ++axis) {
            for (int direction : {-1, +1}) {
              const std::size_t n = grid.neighbour(c, axis, direction);
              if (grid.interior(n) && phase.fraction[n] >= in.diluteFraction) {
                system.anb(c, 2 * axis + (direction > 0 ? 1 : 0)) = 1.0;
                count += 1.0;
              }
            }
          }
          system.ap(c) = count > 0.0 ? count : 1.0;
          continue;
        }
        if (terms.pinned[c] != 0) {
          system.ap(c) = 1.0;
          system.b(c) = terms.pinnedTheta;
          continue;
        }
        double sumNb = 0.0, b = terms.source[c] * V, diagonal = terms.sink[c] * V, correction = 0.0;
        for (int axis = 0; axis < grid.dimensions(); ++axis) {
          const double area = grid.faceArea(axis), h = grid.spacing(axis);
          const fluid::FaceField& F = massFlux[static_cast<std::size_t>(axis)];
          for (int direction : {-1, +1}) {
            const std::size_t n = grid.neighbour(c, axis, direction);
            const int slot = 2 * axis + (direction > 0 ? 1 : 0);
            if (!grid.interior(n) && isWall(boundaries.kind(n))) {
              // Eq. 5.9 through the wall face; nothing conducted or convected.
              b += terms.wallProduction[static_cast<std::size_t>(axis)][c] * area;
              diagonal += terms.wallSink[static_cast<std::size_t>(axis)][c] * area;
              continue;
            }
            const double kappa = grid.interior(n) ? harmonicMean(terms.conductivity[c], terms.conductivity[n])
                                                  : terms.conductivity[c];
            // 3/2 of the mass flux into c through this face.
            const double inflow = 1.5 * (direction > 0 ? std::max(-F[c], 0.0) : std::max(F[n], 0.0));
            const double a = kappa * area / h + inflow;
            system.anb(c, slot) = a;
            sumNb += a;
          }
          // Deferred correction, 3/2 F (theta_superbee - theta_upwind) out through the high face
          // and in through the low face.
          const std::size_t low = grid.neighbour(c, axis, -1);
          const int position = at[static_cast<std::size_t>(axis)];
          correction += 1.5 * (F[c] * correctionAt(grid, theta, c, axis, position, F[c]) -
                               F[low] * correctionAt(grid, theta, low, axis, position - 1, F[low]));
        }
        b -= correction;
        // 3/2 (rho eps)^0 dV / dt: the continuity-subtracted transient.
        const double a0 =
            in.dt > 0.0 ? 1.5 * (*in.oldDensity)[c] * std::max(in.old->phases[m].fraction[c], 0.0) * V / in.dt : 0.0;
        b += a0 * in.old->phases[m].granularTemperature[c];
        diagonal += a0;
        if (b < 0.0) {
          // A negative source (only the deferred correction can leave one) onto the diagonal,
          // so that theta cannot turn negative.
          if (theta[c] > 0.0) diagonal -= b / theta[c];
          b = 0.0;
        }
        if (!(sumNb + diagonal > 0.0)) {
          // Nothing couples this cell (a steady solve of solids at rest and adiabatic): theta stays.
          system.ap(c) = 1.0;
          system.b(c) = theta[c];
          for (int slot = 0; slot < 2 * grid.dimensions(); ++slot) system.anb(c, slot) = 0.0;
          continue;
        }
        system.ap(c) = sumNb + diagonal;
        system.b(c) = b;
      }
    }
  }
  return system;
}

}  // namespace grainbridge::mfm
