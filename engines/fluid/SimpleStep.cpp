#include "engines/fluid/SimpleStep.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "engines/fluid/Continuity.hpp"
#include "engines/fluid/InterphaseCoupling.hpp"
#include "engines/fluid/MassFlux.hpp"
#include "engines/fluid/Momentum.hpp"

namespace grainbridge::fluid {

namespace {

std::string phaseName(const SimpleSettings& settings, std::size_t m) {
  if (m < settings.phaseNames.size() && !settings.phaseNames[m].empty()) return settings.phaseNames[m];
  return m == 0 ? "gas" : "solids " + std::to_string(m);
}

// A solids phase's faces carry no more out of a cell than it held at the step's start (MassFlux);
// the gas fraction is what the solids leave.
OutflowBudget outflowBudget(const FlowState& old, std::size_t m, double dt) {
  if (m == 0 || !(dt > 0.0)) return {};
  return {&old.phases[m].fraction, dt};
}

FlowProperties propertiesFor(const StaggeredGrid& grid, std::size_t phases, const FlowModel& model) {
  FlowProperties p;
  for (std::size_t m = 0; m < phases; ++m) {
    p.phases.emplace_back(grid);
    p.dragCoefficient.emplace_back(grid);
  }
  for (const auto& [l, m] : model.solidsPairs()) p.solidsDrag.emplace_back(grid, l, m);
  if (model.packedFractionByCell()) p.packedFraction.emplace(grid, 0.0);
  return p;
}

// eps_p of Eq. 3.68 at cell c: the model's for the cell, or the settings' everywhere.
double packedFractionAt(const FlowProperties& props, const SimpleSettings& settings, std::size_t c) {
  return props.packedFraction ? (*props.packedFraction)[c] : settings.packedFraction;
}

void copyPropertiesToGhosts(FlowProperties& p, const Boundaries& boundaries) {
  for (PhaseProperties& phase : p.phases) {
    for (CellField* f : {&phase.density, &phase.compressibility, &phase.shearViscosity, &phase.bulkViscosity,
                         &phase.solidsPressure, &phase.plasticPressure, &phase.solidsPressureSlope,
                         &phase.wallSlipCoefficient}) {
      boundaries.copyToGhosts(*f);
    }
    for (CellField& f : phase.momentumSource) boundaries.copyToGhosts(f);
  }
  for (CellField& f : p.dragCoefficient) boundaries.copyToGhosts(f);
  for (SolidsPairDrag& pair : p.solidsDrag) boundaries.copyToGhosts(pair.coefficient);
}

// Keeps the largest residual of an iteration with the equation and cell it belongs to.
struct Worst {
  double value = -1.0;
  std::string equation;
  std::size_t cell = 0;
  void offer(double v, std::string eq, std::size_t c) {
    if (v > value) {
      value = v;
      equation = std::move(eq);
      cell = c;
    }
  }
};

// The continuity residual of a phase: transient, the largest volume-fraction error a cell makes
// over the step, |R| dt / (rho dV); steady, sum |R| over the total throughput.
void offerContinuity(Worst& worst, const std::string& name, const CellField& fraction, const CellField& oldFraction,
                     const CellField& density, const CellField& oldDensity, const std::array<FaceField, 3>& flux,
                     double dt) {
  const StaggeredGrid& grid = fraction.grid();
  double sum = 0.0, throughput = 0.0, largest = -1.0;
  std::size_t at = 0;
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        const double r = std::abs(massImbalance(fraction, oldFraction, density, oldDensity, flux, dt, c));
        const double measure = dt > 0.0 ? r * dt / (density[c] * grid.cellVolume()) : r;
        if (measure > largest) {
          largest = measure;
          at = c;
        }
        sum += r;
        for (int a = 0; a < grid.dimensions(); ++a) throughput += std::abs(flux[static_cast<std::size_t>(a)][c]);
      }
    }
  }
  const double value = dt > 0.0 ? largest : (throughput > 0.0 ? sum / throughput : 0.0);
  worst.offer(value, name + " continuity", at);
}

// MFiX's divergence bound on every velocity (MAX_INLET_VEL, time_march.f and check_vel_bound.f):
// 100 times the largest inflow speed, 500 m/s where nothing flows in. A step whose iterate passes
// it has diverged, whatever its residuals say: they are normalised by the phase's largest speed,
// so a runaway velocity on a thin face hides its own residual (the Goldschmidt binary bed at
// 1.00 m/s carried 7.5e3 m/s on a face at eps_s 6e-3 through converged steps until a step
// emptied cells at any dt).
double velocityBound(const Boundaries& boundaries) {
  double fastest = 0.0;
  for (const BoundaryPatch& patch : boundaries.patches()) {
    if (patch.kind != BoundaryKind::VelocityInlet) continue;
    for (const PhaseInflow& inflow : patch.phases) fastest = std::max(fastest, inflow.velocity.norm());
  }
  return fastest > 0.0 ? 100.0 * fastest : 500.0;
}

// The first non-finite value, fraction out of [0, 1] (beyond round-off) or velocity beyond
// `bound`, described; empty if none.
std::string firstBadValue(const FlowState& state, const FlowProperties& props, const SimpleSettings& settings,
                          double bound, std::array<int, 3>& cell) {
  const StaggeredGrid& grid = state.grid();
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        cell = {i, j, k};
        if (!std::isfinite(state.pressure[c])) return "the gas pressure is not finite";
        const double packed = packedFractionAt(props, settings, c);
        if (state.phases.size() > 1 && packed > 0.0) {
          const double solids = 1.0 - state.phases[0].fraction[c];
          if (solids > packed + settings.overpacking)
            return "the solids fraction is " + std::to_string(solids) + ", beyond eps_s,max " + std::to_string(packed) +
                   " by more than " + std::to_string(settings.overpacking);
        }
        for (std::size_t m = 0; m < state.phases.size(); ++m) {
          const double eps = state.phases[m].fraction[c];
          if (!std::isfinite(eps)) return "the " + phaseName(settings, m) + " fraction is not finite";
          // A solids phase may undershoot zero in a cell it is leaving (a step converges when each
          // cell's continuity is met to the tolerance, not exactly, though the faces preserve
          // positivity at convergence: MassFlux): down to the dilute threshold below zero, a
          // cell the momentum equations already treat as holding no solids, it is such an
          // undershoot, left in place (clipping it would create mass) and seen as zero by the
          // closures; beyond that the step failed. The gas, 1 - sum of the solids, may exceed one
          // by every solids phase's undershoot. (A tenth of the threshold still failed 810 steps in
          // the four 10 s Goldschmidt runs, all at the bed surface between -1.0e-5 and -1.4e-5.)
          const std::size_t solidsPhases = std::max<std::size_t>(state.phases.size() - 1, 1);
          const double undershoot = (m == 0 ? static_cast<double>(solidsPhases) : 1.0) *
                                    (state.phases.size() > 1 ? settings.diluteFraction : 1e-6);
          if (eps < -undershoot || eps > 1.0 + undershoot)
            return "the " + phaseName(settings, m) + " fraction is " + std::to_string(eps) + ", outside [0, 1]";
          for (int a = 0; a < grid.dimensions(); ++a) {
            const double u = state.phases[m].velocity[static_cast<std::size_t>(a)][c];
            if (!std::isfinite(u)) return "a " + phaseName(settings, m) + " velocity is not finite";
            if (std::abs(u) > bound) {
              return "the " + phaseName(settings, m) + " " + std::string(1, "xyz"[a]) + " velocity is " +
                     std::to_string(u) + " m/s, beyond the divergence bound " + std::to_string(bound) +
                     " m/s (100 times the largest inflow speed)";
            }
          }
        }
      }
    }
  }
  return {};
}

// The gas fraction of every interior cell: what the solids phases leave.
void gasFromSolids(FlowState& state) {
  const StaggeredGrid& grid = state.grid();
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (!grid.interior(c)) continue;
    double solids = 0.0;
    for (std::size_t m = 1; m < state.phases.size(); ++m) solids += state.phases[m].fraction[c];
    state.phases[0].fraction[c] = 1.0 - solids;
  }
}

// A converged step's solids fractions, each phase's continuity solved implicitly with the
// converged faces (Continuity.hpp): exact mass balance and no undershoot below zero, which the
// iteration's tolerance alone leaves in thin cells; the gas is what the solids leave.
// Fills each solved solids phase's boundary flows (the rest stay zero).
void closeSolidsContinuity(FlowState& state, const FlowState& old, const FlowProperties& props,
                           const FlowProperties& oldProps, const Boundaries& boundaries, double dt,
                           const std::vector<char>& given, const LinearSolve& how,
                           std::vector<std::vector<PatchFlow>>& boundaryFlow) {
  for (std::size_t m = 1; m < state.phases.size(); ++m) {
    if (given[m] != 0) continue;
    PhaseFields& phase = state.phases[m];
    const auto flux = massFluxes(phase, props.phases[m].density, boundaries, outflowBudget(old, m, dt), m);
    const auto moved = solveFractionNonNegative(phase, old.phases[m].fraction, props.phases[m].density,
                                                oldProps.phases[m].density, flux, boundaries, dt, how);
    boundaryFlow[m] = patchFlows(moved, boundaries);
  }
  gasFromSolids(state);
  boundaries.apply(state, &props);
}

// Runs a system's solve, naming the system in the SingularSystem it may throw (the solver names
// the cell), so that a failed step says which equation broke.
template <class Solve>
void solveNamed(std::string_view system, Solve&& solve) {
  try {
    solve();
  } catch (const SingularSystem& e) {
    throw SingularSystem(std::string(system) + ": " + e.what());
  }
}

// The gas's continuity closed with the step's final fractions, once the solids' are (the gas is
// what they leave): the SIMPLE loop meets it to the tolerance only, with the last iterate's
// fractions, and each step's remainder would add up in the gas's mass balance (1.6e-4 of the
// inflow over the combine's 10 s). One more pressure correction, from the final fractions'
// imbalance and the last iteration's coefficients d, moves the gas's face velocities only, so its
// faces carry exactly what each cell's gas gains (to the linear solve's tolerance); the pressure
// keeps the converged iterate's, the correction being a continuity residual's size. Not for a
// compressible gas, whose density follows the pressure.
void closeGasContinuity(FlowState& state, const FlowState& old, const FlowProperties& props,
                        const FlowProperties& oldProps, const Boundaries& boundaries,
                        const std::array<const FaceField*, 3>& d, const LinearSolve& how, double dt) {
  const StaggeredGrid& grid = state.grid();
  for (double compressibility : props.phases[0].compressibility.values()) {
    if (compressibility > 0.0) return;
  }
  const auto gasFlux = massFluxes(state.phases[0], props.phases[0].density, boundaries);
  const StencilSystem system = assemblePressureCorrection(state, old, props, oldProps, boundaries, gasFlux, d, dt);
  CellField correction(grid, 0.0);
  solveNamed("the gas's closing pressure correction", [&] { system.solve(correction, how); });
  for (int a = 0; a < grid.dimensions(); ++a) {
    FaceField& u = state.phases[0].velocity[static_cast<std::size_t>(a)];
    const FaceField& da = *d[static_cast<std::size_t>(a)];
    for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
      if (boundaries.solvedFace(a, f)) u[f] -= da[f] * (correction[grid.neighbour(f, a, +1)] - correction[f]);
    }
  }
  boundaries.apply(state, &props);
}

StepResult iterate(FlowState& state, const FlowState& old, double dt, const FlowModel& model,
                   const Boundaries& boundaries, const SimpleSettings& settings) {
  const StaggeredGrid& grid = state.grid();
  const std::size_t M = state.phases.size();
  const int dims = grid.dimensions();
  std::vector<char> given(M, 0);
  for (std::size_t m = 1; m < M; ++m) given[m] = model.givenPhase(m) ? 1 : 0;
  FlowProperties props = propertiesFor(grid, M, model);
  // The last time level's properties (its densities, for the transient terms), evaluated once.
  FlowProperties oldProps = propertiesFor(grid, M, model);
  model.evaluate(old, oldProps);
  copyPropertiesToGhosts(oldProps, boundaries);
  MomentumInputs in;
  in.state = &state;
  in.old = &old;
  in.properties = &props;
  in.oldProperties = &oldProps;
  in.boundaries = &boundaries;
  in.gravity = settings.gravity;
  in.dt = dt;
  in.diluteFraction = settings.diluteFraction;

  const double bound = velocityBound(boundaries);
  StepResult result;
  std::vector<CorrectionCoefficients> corrections;  // the last iteration's, for the closing
  double windowResidual = 0.0;                      // at the last multiple of stallWindow
  for (int iteration = 1; iteration <= settings.maxIterations; ++iteration) {
    result.iterations = iteration;
    Worst worst;
    // Partial-slip walls take the last evaluated properties' coefficients (the old level's on the
    // first iteration), then this iteration's.
    boundaries.apply(state, iteration == 1 ? &oldProps : &props);
    model.evaluate(state, props);
    copyPropertiesToGhosts(props, boundaries);
    boundaries.apply(state, &props);

    // 2. Momentum of every phase, component by component, with the drag eliminated.
    // (A given phase's momentum is not assembled: it needs no fluxes.)
    std::vector<std::array<FaceField, 3>> flux;
    for (std::size_t m = 0; m < M; ++m) {
      flux.push_back(given[m] != 0
                         ? std::array<FaceField, 3>{FaceField(grid, 0), FaceField(grid, 1), FaceField(grid, 2)}
                         : massFluxes(state.phases[m], props.phases[m].density, boundaries, outflowBudget(old, m, dt), m));
    }
    std::vector<double> speed(M, settings.velocityScale);
    for (std::size_t m = 0; m < M; ++m) {
      for (int a = 0; a < dims; ++a) {
        for (double u : state.phases[m].velocity[static_cast<std::size_t>(a)].values())
          speed[m] = std::max(speed[m], std::abs(u));
      }
    }
    corrections.clear();
    for (int a = 0; a < dims; ++a) {
      std::vector<StencilSystem> systems;
      for (std::size_t m = 0; m < M; ++m)
        systems.push_back(given[m] != 0 ? StencilSystem::unsolved(grid) : assembleMomentum(in, m, a, flux[m]));
      corrections.push_back(
          coupleAndRelax(systems, state, props, a, settings.momentumRelaxation, settings.diluteFraction, given));
      for (std::size_t m = 0; m < M; ++m) {
        if (given[m] != 0) continue;
        FaceField& u = state.phases[m].velocity[static_cast<std::size_t>(a)];
        const auto r = systems[m].normalisedResidual(u.values(), speed[m]);
        const std::string equation = phaseName(settings, m) + " " + std::string(1, "xyz"[a]) + " momentum";
        worst.offer(r.value, equation, r.worst);
        solveNamed(equation, [&] { systems[m].solve(u, settings.momentumSolve); });
      }
    }
    for (int a = dims; a < 3; ++a) corrections.emplace_back();
    boundaries.apply(state, &props);

    // 3. Gas pressure correction.
    const auto gasFlux = massFluxes(state.phases[0], props.phases[0].density, boundaries);
    offerContinuity(worst, "gas", state.phases[0].fraction, old.phases[0].fraction, props.phases[0].density,
                    oldProps.phases[0].density, gasFlux, dt);
    std::array<const FaceField*, 3> d{nullptr, nullptr, nullptr};
    for (int a = 0; a < dims; ++a)
      d[static_cast<std::size_t>(a)] = &corrections[static_cast<std::size_t>(a)].pressure[0];
    const StencilSystem pressureSystem =
        assemblePressureCorrection(state, old, props, oldProps, boundaries, gasFlux, d, dt);
    CellField pressureCorrection(grid, 0.0);
    solveNamed("the pressure correction", [&] { pressureSystem.solve(pressureCorrection.values(), settings.pressureSolve); });
    for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
      if (grid.interior(c)) state.pressure[c] += settings.pressureRelaxation * pressureCorrection[c];
    }
    for (int a = 0; a < dims; ++a) {
      for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
        if (!boundaries.solvedFace(a, f)) continue;
        const double dp = pressureCorrection[grid.neighbour(f, a, +1)] - pressureCorrection[f];
        for (std::size_t m = 0; m < M; ++m) {
          state.phases[m].velocity[static_cast<std::size_t>(a)][f] -=
              corrections[static_cast<std::size_t>(a)].pressure[m][f] * dp;
        }
      }
    }

    // 4. Solids fraction corrections (Eqs. 3.68-3.69).
    for (std::size_t m = 1; m < M; ++m) {
      if (given[m] != 0) continue;
      boundaries.apply(state, &props);
      PhaseFields& phase = state.phases[m];
      const auto solidsFlux = massFluxes(phase, props.phases[m].density, boundaries, outflowBudget(old, m, dt), m);
      const std::string name = phaseName(settings, m);
      offerContinuity(worst, name, phase.fraction, old.phases[m].fraction, props.phases[m].density,
                      oldProps.phases[m].density, solidsFlux, dt);
      std::array<const FaceField*, 3> e{nullptr, nullptr, nullptr};
      for (int a = 0; a < dims; ++a)
        e[static_cast<std::size_t>(a)] = &corrections[static_cast<std::size_t>(a)].solidsPressure[m];
      const StencilSystem fractionSystem =
          assembleFractionCorrection(state, old, props, oldProps, m, solidsFlux, e, dt);
      CellField fractionCorrection(grid, 0.0);
      solveNamed(name + " fraction correction",
                 [&] { fractionSystem.solve(fractionCorrection, settings.fractionSolve); });
      // The correction conserves the phase's mass exactly (its fluxes telescope); Eq. 3.68's
      // relaxation withholds part of it, which the next iteration hands back. A step converges
      // only once what was withheld is negligible, so under-relaxation never leaks mass.
      double withheld = 0.0, inventory = 0.0;
      for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
        if (!grid.interior(c)) continue;
        double& correction = fractionCorrection[c];
        // Eq. 3.68 on the total solids fraction: a mixture packs as a whole, each of its phases
        // far below eps_s,max (the phases corrected before m already hold their new values).
        double solids = 0.0;
        for (std::size_t l = 1; l < M; ++l) solids += state.phases[l].fraction[c];
        if (solids + correction > packedFractionAt(props, settings, c) && correction > 0.0) {
          withheld += (1.0 - settings.fractionRelaxation) * correction;
          correction *= settings.fractionRelaxation;  // Eq. 3.68
        }
        phase.fraction[c] += correction;  // Eq. 3.69
        inventory += std::abs(phase.fraction[c]);
      }
      if (inventory > 0.0) {
        worst.offer(withheld / inventory / settings.massTolerance * settings.tolerance,
                    phaseName(settings, m) + " packing relaxation", worst.cell);
      }
      const CellField& slope = props.phases[m].solidsPressureSlope;
      for (int a = 0; a < dims; ++a) {
        FaceField& u = phase.velocity[static_cast<std::size_t>(a)];
        const FaceField& ea = *e[static_cast<std::size_t>(a)];
        for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
          if (!boundaries.solvedFace(a, f)) continue;
          u[f] -=
              ea[f] * meanOnFace(slope, a, f) * (fractionCorrection[grid.neighbour(f, a, +1)] - fractionCorrection[f]);
        }
      }
    }
    if (M > 1) gasFromSolids(state);

    // 5. The model's own transport equations (granular energy).
    boundaries.apply(state, &props);
    for (const TransportResidual& r : model.solveTransport(state, old, props, oldProps, boundaries, dt))
      worst.offer(r.value, r.equation, r.cell);

    result.residual = worst.value;
    result.equation = worst.equation;
    result.cell = grid.coordinates(worst.cell);
    std::array<int, 3> badCell{};
    result.failure = firstBadValue(state, props, settings, bound, badCell);
    if (!result.failure.empty()) {
      result.cell = badCell;
      return result;
    }
    if (worst.value >= settings.tolerance && settings.stallWindow > 0 && iteration % settings.stallWindow == 0) {
      if (iteration > 2 * settings.stallWindow && windowResidual <= worst.value) {
        result.stalledAt = iteration;
        return result;
      }
      windowResidual = worst.value;
    }
    if (worst.value < settings.tolerance) {
      result.converged = true;
      boundaries.apply(state, &props);
      if (dt > 0.0) {
        result.boundaryFlow.assign(M, std::vector<PatchFlow>(boundaries.patches().size()));
        if (M > 1) closeSolidsContinuity(state, old, props, oldProps, boundaries, dt, given, settings.fractionSolve,
                                       result.boundaryFlow);
        std::array<const FaceField*, 3> gasD{nullptr, nullptr, nullptr};
        for (int a = 0; a < dims; ++a)
          gasD[static_cast<std::size_t>(a)] = &corrections[static_cast<std::size_t>(a)].pressure[0];
        closeGasContinuity(state, old, props, oldProps, boundaries, gasD, settings.pressureSolve, dt);
        result.boundaryFlow[0] =
            patchFlows(massFluxes(state.phases[0], props.phases[0].density, boundaries), boundaries);
      }
      return result;
    }
  }
  return result;
}

// Iterates from `start` (the state as the caller passed it), leaving `state` at the new level when
// the step converged and at `start` otherwise.
StepResult advanceFrom(FlowState& state, const FlowState& start, const FlowState& old, double dt,
                       const FlowModel& model, const Boundaries& boundaries, const SimpleSettings& settings) {
  StepResult result;
  try {
    result = iterate(state, old, dt, model, boundaries, settings);
  } catch (const SingularSystem& e) {
    // A bad iterate: the step failed, as one that does not converge (a smaller one is tried).
    result.converged = false;
    result.failure = e.what();
  } catch (...) {
    state = start;  // whatever stops the run leaves the state it was given, never an iterate
    throw;
  }
  if (result.converged) {
    state.time = old.time + dt;
  } else {
    state = start;
  }
  return result;
}

}  // namespace

StepResult advance(FlowState& state, double dt, const FlowModel& model, const Boundaries& boundaries,
                   const SimpleSettings& settings) {
  const FlowState old = state;
  return advanceFrom(state, old, old, dt, model, boundaries, settings);
}

StepResult advance(FlowState& state, const FlowState& old, double dt, const FlowModel& model,
                   const Boundaries& boundaries, const SimpleSettings& settings) {
  gasFromSolids(state);  // the given phases' new fractions leave the gas its own
  const FlowState start = state;
  return advanceFrom(state, start, old, dt, model, boundaries, settings);
}

StepResult solveSteady(FlowState& state, const FlowModel& model, const Boundaries& boundaries,
                       const SimpleSettings& settings) {
  const FlowState old = state;
  return iterate(state, old, 0.0, model, boundaries, settings);
}

}  // namespace grainbridge::fluid
