#include "engines/fluid/Continuity.hpp"

#include <algorithm>
#include <cmath>

#include "engines/fluid/MassFlux.hpp"
#include "engines/fluid/Momentum.hpp"

namespace grainbridge::fluid {

double massImbalance(const CellField& fraction, const CellField& oldFraction, const CellField& density,
                     const CellField& oldDensity, const std::array<FaceField, 3>& flux, double dt, std::size_t c) {
  const StaggeredGrid& grid = fraction.grid();
  // rho (eps - eps0) when the density has not changed (an incompressible phase): the same value
  // as rho eps - rho0 eps0, rounded once, so incompressible runs do not depend on the form.
  const double accumulation = density[c] == oldDensity[c] ? density[c] * (fraction[c] - oldFraction[c])
                                                          : density[c] * fraction[c] - oldDensity[c] * oldFraction[c];
  double r = dt > 0.0 ? accumulation * grid.cellVolume() / dt : 0.0;
  for (int a = 0; a < grid.dimensions(); ++a) {
    const FaceField& F = flux[static_cast<std::size_t>(a)];
    r += F[c] - F[grid.neighbour(c, a, -1)];
  }
  return r;
}

StencilSystem assemblePressureCorrection(const FlowState& state, const FlowState& old, const FlowProperties& properties,
                                         const FlowProperties& oldProperties, const Boundaries& boundaries,
                                         const std::array<FaceField, 3>& gasFlux,
                                         const std::array<const FaceField*, 3>& d, double dt) {
  const StaggeredGrid& grid = state.grid();
  const PhaseFields& gas = state.phases[0];
  const CellField& rho = properties.phases[0].density;
  StencilSystem system(grid);
  bool anyCompressible = false;
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        double sum = 0.0;
        for (int a = 0; a < grid.dimensions(); ++a) {
          const double A = grid.faceArea(a);
          const FaceField& v = gas.velocity[static_cast<std::size_t>(a)];
          const std::size_t low = grid.neighbour(c, a, -1), high = grid.neighbour(c, a, +1);
          const FaceField& da = *d[static_cast<std::size_t>(a)];
          const double aHigh = rho[v[c] >= 0.0 ? c : high] * faceFraction(gas.fraction, a, c, v[c]) * A * da[c];
          const double aLow = rho[v[low] >= 0.0 ? low : c] * faceFraction(gas.fraction, a, low, v[low]) * A * da[low];
          system.anb(c, 2 * a + 1) = aHigh;
          system.anb(c, 2 * a) = aLow;
          sum += aHigh + aLow;
        }
        const double compressible =
            dt > 0.0 ? gas.fraction[c] * grid.cellVolume() / dt * properties.phases[0].compressibility[c] : 0.0;
        anyCompressible = anyCompressible || compressible > 0.0;
        system.ap(c) = sum + compressible;
        system.b(c) =
            -massImbalance(gas.fraction, old.phases[0].fraction, rho, oldProperties.phases[0].density, gasFlux, dt, c);
      }
    }
  }
  if (!boundaries.hasOutlet() && !anyCompressible) {
    const std::size_t first = grid.index(0, 0, 0);
    system.ap(first) = 1.0;
    for (int nb = 0; nb < 2 * grid.dimensions(); ++nb) system.anb(first, nb) = 0.0;
    system.b(first) = 0.0;
  }
  return system;
}

StencilSystem assembleFractionCorrection(const FlowState& state, const FlowState& old, const FlowProperties& properties,
                                         const FlowProperties& oldProperties, std::size_t m,
                                         const std::array<FaceField, 3>& flux, const std::array<const FaceField*, 3>& e,
                                         double dt) {
  const StaggeredGrid& grid = state.grid();
  const PhaseFields& phase = state.phases[m];
  const CellField& rho = properties.phases[m].density;
  const CellField& slope = properties.phases[m].solidsPressureSlope;
  StencilSystem system(grid);
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        double ap = dt > 0.0 ? rho[c] * grid.cellVolume() / dt : 0.0;
        for (int a = 0; a < grid.dimensions(); ++a) {
          const double A = grid.faceArea(a);
          const FaceField& v = phase.velocity[static_cast<std::size_t>(a)];
          const FaceField& ea = *e[static_cast<std::size_t>(a)];
          const std::size_t low = grid.neighbour(c, a, -1);
          // Diffusion-like part: the solids pushed by the solids-pressure change.
          const double diffHigh =
              rho[c] * faceFraction(phase.fraction, a, c, v[c]) * A * ea[c] * meanOnFace(slope, a, c);
          const double diffLow =
              rho[c] * faceFraction(phase.fraction, a, low, v[low]) * A * ea[low] * meanOnFace(slope, a, low);
          const double outHigh = rho[c] * A * std::max(v[c], 0.0), inHigh = rho[c] * A * std::max(-v[c], 0.0);
          const double inLow = rho[c] * A * std::max(v[low], 0.0), outLow = rho[c] * A * std::max(-v[low], 0.0);
          system.anb(c, 2 * a + 1) = diffHigh + inHigh;
          system.anb(c, 2 * a) = diffLow + inLow;
          ap += diffHigh + diffLow + outHigh + outLow;
        }
        system.ap(c) = ap;
        system.b(c) =
            -massImbalance(phase.fraction, old.phases[m].fraction, rho, oldProperties.phases[m].density, flux, dt, c);
      }
    }
  }
  return system;
}

std::array<FaceField, 3> solveFractionNonNegative(PhaseFields& phase, const CellField& oldFraction,
                                                  const CellField& density, const CellField& oldDensity,
                                                  const std::array<FaceField, 3>& flux, const Boundaries& boundaries,
                                                  double dt, const LinearSolve& how) {
  const StaggeredGrid& grid = phase.fraction.grid();
  const CellField& eps = phase.fraction;
  StencilSystem system(grid);
  const double volumeRate = grid.cellVolume() / dt;
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        system.ap(c) += density[c] * volumeRate;
        system.b(c) = oldDensity[c] * oldFraction[c] * volumeRate;
      }
    }
  }
  // Each open face's signed c_f, kept to give the fluxes of the solved fractions.
  std::array<FaceField, 3> moved{FaceField(grid, 0), FaceField(grid, 1), FaceField(grid, 2)};
  for (int a = 0; a < grid.dimensions(); ++a) {
    const FaceField& v = phase.velocity[static_cast<std::size_t>(a)];
    const FaceField& F = flux[static_cast<std::size_t>(a)];
    for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
      if (!boundaries.openFace(a, f)) continue;
      const std::size_t high = grid.neighbour(f, a, +1);
      const bool forward = v[f] >= 0.0;
      const std::size_t upwind = forward ? f : high, downwind = forward ? high : f;
      // An empty upwind cell moves what it will hold at rho A |v|. An empty (or round-off
      // negative) upwind ghost brings nothing: what comes in through a boundary face is F's, the
      // backflow state's at an outlet, which a ghost holding no solids has none of (a ghost that
      // repeats an interior at -3e-16 brought that negative mass in at every step: it doubled each
      // step until the top row of the combine's feed column went below -1e-4 and failed the step).
      double coefficient = density[upwind] * grid.faceArea(a) * std::abs(v[f]);
      if (eps[upwind] > 0.0) {
        coefficient = std::abs(F[f]) / eps[upwind];
      } else if (!grid.interior(upwind)) {
        coefficient = 0.0;
      }
      // Out of the upwind cell (its diagonal), into the downwind one (its neighbour slot facing
      // upwind); a ghost on either side is a known value or no equation.
      if (grid.interior(upwind)) system.ap(upwind) += coefficient;
      if (grid.interior(downwind)) system.anb(downwind, forward ? 2 * a : 2 * a + 1) += coefficient;
      moved[static_cast<std::size_t>(a)][f] = forward ? coefficient : -coefficient;
    }
  }
  // c_f eps_upwind on every open face, at the fractions `at`.
  const auto fluxesAt = [&](const CellField& at) {
    std::array<FaceField, 3> F = moved;
    for (int a = 0; a < grid.dimensions(); ++a) {
      const FaceField& v = phase.velocity[static_cast<std::size_t>(a)];
      FaceField& Fa = F[static_cast<std::size_t>(a)];
      for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
        if (Fa[f] != 0.0) Fa[f] *= at[v[f] >= 0.0 ? f : grid.neighbour(f, a, +1)];
      }
    }
    return F;
  };
  if (how.method != LinearSolve::Method::Direct) {
    const CellField start = phase.fraction;
    system.solve(phase.fraction, how);
    // The flux-form finish: r_c / (rho dV/dt) is what the iterate's fluxes leave in cell c
    // beyond eps*_c (the residuals of all cells sum to in - out, the faces cancelling). A thin
    // cell the solids are leaving can end a round-off below zero (-1e-20 in the combine's
    // front): set to zero, which drops that round-off's mass, as long as all it drops is within
    // kRoundOff of the phase's mass; anything more means the sweeps went wrong: the LU instead.
    constexpr double kRoundOff = 1e-15;
    std::vector<double> finished(grid.paddedCount(), 0.0);
    double held = 0.0, dropped = 0.0;
    for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
      if (!grid.interior(c)) continue;
      const double residual = system.neighbourSum(c, eps.values()) - system.ap(c) * eps[c];
      finished[c] = eps[c] + residual / (density[c] * volumeRate);
      (finished[c] >= 0.0 ? held : dropped) += density[c] * std::abs(finished[c]);
    }
    if (dropped <= kRoundOff * held) {
      auto F = fluxesAt(phase.fraction);
      for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
        if (grid.interior(c)) phase.fraction[c] = std::max(finished[c], 0.0);
      }
      return F;
    }
    phase.fraction = start;
  }
  system.solve(phase.fraction);
  return fluxesAt(phase.fraction);
}

}  // namespace grainbridge::fluid
