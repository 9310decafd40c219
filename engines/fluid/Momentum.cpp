#include "engines/fluid/Momentum.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "engines/fluid/SuperbeeOnGrid.hpp"

namespace grainbridge::fluid {

namespace {

// Superbee minus upwind value of the transported component `u` on the control-volume face
// between the faces `f` and `f + e_b` (f at `position` along b), for the flux F through it.
double correction(const StaggeredGrid& grid, const FaceField& u, std::size_t f, int b, int position, double F) {
  return superbeeOnGrid(grid, u, f, b, position, F) - upwindOnGrid(grid, u, f, b, F);
}

// div(v) of a phase at cell c from its face velocities.
double divergence(const StaggeredGrid& grid, const PhaseFields& phase, std::size_t c) {
  double div = 0.0;
  for (int b = 0; b < grid.dimensions(); ++b) {
    const FaceField& v = phase.velocity[static_cast<std::size_t>(b)];
    div += (v[c] - v[grid.neighbour(c, b, -1)]) / grid.spacing(b);
  }
  return div;
}

// MFiX's rule for a dilute face: the mean of the neighbouring faces of the same component whose
// cells (the neighbour face's far cell) hold solids above the threshold; none: the current value.
void diluteEquation(StencilSystem& system, const PhaseFields& phase, const Boundaries& boundaries, int a, std::size_t f,
                    double threshold) {
  const StaggeredGrid& grid = phase.fraction.grid();
  double count = 0.0;
  for (int d = 0; d < grid.dimensions(); ++d) {
    for (int direction : {-1, +1}) {
      const std::size_t n = grid.neighbour(f, d, direction);
      const bool solids = meanOnFace(phase.fraction, a, n) > threshold;
      if (solids && boundaries.solvedFace(a, n)) {
        system.anb(f, 2 * d + (direction > 0 ? 1 : 0)) = 1.0;
        count += 1.0;
      }
    }
  }
  system.ap(f) = count > 0.0 ? count : 1.0;
  system.b(f) = count > 0.0 ? 0.0 : phase.velocity[static_cast<std::size_t>(a)][f];
}

// With several solids phases, phase m feels its volume share of the mixture's plastic pressure
// gradient, (eps_sm / eps_s) grad(sum_l eps_sl P*), as MFiX gives each close-packed phase
// EP_s(M)/SUM_EPS_CP of grad P* (source_v_s.f), instead of the gradient of its own eps_sm P*:
// that one holds P* grad(eps_sm), which at a packed bed's edge, where a thin phase's fraction
// changes by decades from cell to cell, pushes that phase's little mass with the whole packing
// pressure (the binary bed at 1.00 m/s: large particles at 1e-3 reached 100 m/s and more).
// Identical phases still add up to one phase: the shares sum to one. Returns what to add to
// the face's pressure-gradient force, -(own plastic gradient) + share * mixture gradient, times
// the face area, in the sign of `b -= ...`. A correction on top of solidsPressure's gradient,
// not a split of it into kinetic and plastic parts, so that one solids phase (share 1) keeps
// the same floating-point sum and its results bit for bit.
double mixturePlasticCorrection(const FlowState& state, const FlowProperties& props, std::size_t m, int a,
                                std::size_t f) {
  const StaggeredGrid& grid = state.grid();
  const std::size_t E = grid.neighbour(f, a, +1);
  double mixtureE = 0.0, mixtureP = 0.0, solids = 0.0;
  for (std::size_t l = 1; l < state.phases.size(); ++l) {
    mixtureE += props.phases[l].plasticPressure[E];
    mixtureP += props.phases[l].plasticPressure[f];
    solids += std::max(meanOnFace(state.phases[l].fraction, a, f), 0.0);
  }
  const double share = solids > 0.0 ? std::max(meanOnFace(state.phases[m].fraction, a, f), 0.0) / solids : 0.0;
  const CellField& own = props.phases[m].plasticPressure;
  return (share * (mixtureE - mixtureP) - (own[E] - own[f])) * grid.faceArea(a);
}

}  // namespace

bool diluteFace(const FlowState& state, std::size_t m, int axis, std::size_t face, double threshold) {
  return m > 0 && meanOnFace(state.phases[m].fraction, axis, face) < threshold;
}

StencilSystem assembleMomentum(const MomentumInputs& in, std::size_t m, int a, const std::array<FaceField, 3>& flux) {
  const FlowState& state = *in.state;
  const StaggeredGrid& grid = state.grid();
  const PhaseFields& phase = state.phases[m];
  const PhaseFields& old = in.old->phases[m];
  const PhaseProperties& props = in.properties->phases[m];
  const FaceField& u = phase.velocity[static_cast<std::size_t>(a)];
  const CellField& mu = props.shearViscosity;
  const double V = grid.cellVolume();
  const int na = grid.cells(a);

  StencilSystem system(grid);
  for (std::size_t f = 0; f < grid.paddedCount(); ++f) system.setActive(f, in.boundaries->solvedFace(a, f));
  // Each control-volume face is the high face of one velocity face and the low face of the next
  // along d: its deferred correction F (superbee - upwind), worked out as the high face's, is kept
  // for the next face's low side (the same operands in the same order, so the same bits).
  std::array<std::vector<double>, 3> highCorrection;
  std::array<std::vector<char>, 3> highDone;
  for (int d = 0; d < grid.dimensions(); ++d) {
    highCorrection[static_cast<std::size_t>(d)].assign(grid.paddedCount(), 0.0);
    highDone[static_cast<std::size_t>(d)].assign(grid.paddedCount(), 0);
  }

  // div(v) of the cells on either side of the active faces, each worked out once (a cell is E of
  // one face and P of the next).
  const CellField& lambda = props.bulkViscosity;
  std::vector<double> cellDivergence(grid.paddedCount(), 0.0);
  std::vector<char> divergenceDone(grid.paddedCount(), 0);
  const auto divergenceAt = [&](std::size_t c) {
    if (divergenceDone[c] == 0) {
      cellDivergence[c] = divergence(grid, phase, c);
      divergenceDone[c] = 1;
    }
    return cellDivergence[c];
  };

  for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
    if (!system.active(f)) continue;
    const auto at = grid.coordinates(f);
    const std::size_t P = f, E = grid.neighbour(f, a, +1);
    const int ia = at[static_cast<std::size_t>(a)];
    const double eps = meanOnFace(phase.fraction, a, f);
    const double rho = meanOnFace(props.density, a, f);
    if (diluteFace(state, m, a, f, in.diluteFraction)) {
      diluteEquation(system, phase, *in.boundaries, a, f, in.diluteFraction);
      continue;
    }
    double sumNb = 0.0, b = 0.0;
    {
      for (int d = 0; d < grid.dimensions(); ++d) {
        const double area = grid.faceArea(d), h = grid.spacing(d);
        const FaceField& Fd = flux[static_cast<std::size_t>(d)];
        double Fhi = 0.0, Flo = 0.0, muHi = 0.0, muLo = 0.0, transposed = 0.0;
        if (d == a) {
          // Control-volume faces at the centres of cells E and P.
          Fhi = ia == na - 1 ? Fd[f] : 0.5 * (Fd[f] + Fd[E]);
          Flo = ia == -1 ? Fd[f] : 0.5 * (Fd[grid.neighbour(f, a, -1)] + Fd[f]);
          muHi = mu[E];
          muLo = mu[P];
          const double uW = ia == -1 ? u[f] : u[grid.neighbour(f, a, -1)];
          transposed = (muHi * (u[E] - u[f]) - muLo * (u[f] - uW)) / h * area;
        } else {
          // Control-volume faces on the edges between P, E and their neighbours along d.
          const std::size_t Pl = grid.neighbour(P, d, -1), El = grid.neighbour(E, d, -1);
          const std::size_t Ph = grid.neighbour(P, d, +1), Eh = grid.neighbour(E, d, +1);
          Fhi = 0.5 * (Fd[P] + Fd[E]);
          Flo = 0.5 * (Fd[Pl] + Fd[El]);
          muHi = 0.25 * (mu[P] + mu[E] + mu[Ph] + mu[Eh]);
          muLo = 0.25 * (mu[P] + mu[E] + mu[Pl] + mu[El]);
          const FaceField& vd = phase.velocity[static_cast<std::size_t>(d)];
          const double ha = grid.spacing(a);
          transposed = (muHi * (vd[E] - vd[P]) - muLo * (vd[El] - vd[Pl])) / ha * area;
        }
        const double aHi = muHi * area / h + std::max(-Fhi, 0.0);
        const double aLo = muLo * area / h + std::max(Flo, 0.0);
        system.anb(f, 2 * d + 1) = aHi;
        system.anb(f, 2 * d) = aLo;
        sumNb += aHi + aLo;
        const int position = at[static_cast<std::size_t>(d)];
        const std::size_t low = grid.neighbour(f, d, -1);
        const double high = Fhi * correction(grid, u, f, d, position, Fhi);
        highCorrection[static_cast<std::size_t>(d)][f] = high;
        highDone[static_cast<std::size_t>(d)][f] = 1;
        // A face in the first layer along d has no face before it in the grid (along a, ia = -1
        // takes its own flux as the low one).
        const bool kept = position >= 0 && highDone[static_cast<std::size_t>(d)][low] != 0;
        b -= high - (kept ? highCorrection[static_cast<std::size_t>(d)][low]
                          : Flo * correction(grid, u, low, d, position - 1, Flo));
        b += transposed;
      }
      b += (lambda[E] * divergenceAt(E) - lambda[P] * divergenceAt(P)) * grid.faceArea(a);
    }
    // (rho eps)^0 of the control volume: the continuity-subtracted transient.
    const double a0 =
        in.dt > 0.0 ? meanOnFace(in.oldProperties->phases[m].density, a, f) * meanOnFace(old.fraction, a, f) * V / in.dt
                    : 0.0;
    system.ap(f) = sumNb + a0;
    b += a0 * old.velocity[static_cast<std::size_t>(a)][f];
    b -= eps * (state.pressure[E] - state.pressure[P]) * grid.faceArea(a);
    if (m > 0) b -= (props.solidsPressure[E] - props.solidsPressure[P]) * grid.faceArea(a);
    if (m > 0 && state.phases.size() > 2) b -= mixturePlasticCorrection(state, *in.properties, m, a, f);
    b += eps * rho * in.gravity[a] * V;
    if (!props.momentumSource.empty()) b += meanOnFace(props.momentumSource[static_cast<std::size_t>(a)], a, f) * V;
    system.b(f) = b;
  }
  return system;
}

}  // namespace grainbridge::fluid
