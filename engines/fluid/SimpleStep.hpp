#pragma once
// One time step of the multiphase flow by the modified SIMPLE method of Section 3.3.3 (MFiX's
// algorithm, Syamlal 1998), iterated until the normalised residuals fall below the tolerance:
//   1. the model evaluates each phase's properties and the drag at the current iterate;
//   2. every phase's momentum, each component, with the drag by partial elimination, solved;
//   3. the gas pressure correction from the gas continuity, P += omega_P P', every phase's
//      velocity corrected (the correction coefficients carry the drag);
//   4. per solids phase, the fraction correction from its continuity, under-relaxed as Eq. 3.68
//      says where the bed (all solids phases together) is packed, eps_s += eps_s' (Eq. 3.69),
//      its velocity corrected;
//      eps_g = 1 - sum eps_s. No fraction is ever clipped: clipping would break conservation.
// The step either converges (the state is the new time level) or reports which equation, cell
// and residual kept it from converging, and leaves the state at the old level, so the caller can
// retry with a smaller step.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/BoundaryFlow.hpp"
#include "engines/fluid/FlowState.hpp"
#include "engines/fluid/PhaseProperties.hpp"
#include "engines/fluid/StencilSystem.hpp"

namespace grainbridge::fluid {

// The largest normalised residual of a transport equation a model solves itself, with its name
// ("solids 1 granular energy") and the padded cell where it is largest.
struct TransportResidual {
  double value = 0.0;
  std::string equation;
  std::size_t cell = 0;
};

// The model side: fills `properties` (sized for the grid and the phase count) at `state`.
class FlowModel {
 public:
  virtual ~FlowModel() = default;
  virtual void evaluate(const FlowState& state, FlowProperties& properties) const = 0;
  // The pairs (l, m), 1 <= l < m, of solids phases that exchange momentum (Eq. 3.18): evaluate()
  // fills FlowProperties::solidsDrag for them, in this order.
  [[nodiscard]] virtual std::vector<std::array<std::size_t, 2>> solidsPairs() const { return {}; }
  // Whether solids phase m is given, not solved: its fraction and velocity are the caller's (TF-DEM's
  // particles deposited on the grid, Section 7.2.3). The step solves neither its momentum nor its
  // continuity; every other phase sees its exchange implicitly at its given velocity (as a dilute
  // face's, InterphaseCoupling.hpp), and the gas continuity sees its fraction change over the step.
  [[nodiscard]] virtual bool givenPhase(std::size_t /*m*/) const { return false; }
  // Whether evaluate() gives each cell its own packed solids fraction (FlowProperties::
  // packedFraction: a mixture's packing limit by composition) in place of SimpleSettings'.
  [[nodiscard]] virtual bool packedFractionByCell() const { return false; }
  // Equations of the model's own beyond mass and momentum (a kinetic-theory model's granular
  // energy, Eq. 3.34), solved once per outer iteration after the continuity corrections, at the
  // iterate's velocities and fractions and the `properties` evaluated at its start. Each returns
  // its residual before the solve, which the step's convergence test reads with the others.
  virtual std::vector<TransportResidual> solveTransport(FlowState& /*state*/, const FlowState& /*old*/,
                                                        const FlowProperties& /*properties*/,
                                                        const FlowProperties& /*oldProperties*/,
                                                        const Boundaries& /*boundaries*/, double /*dt*/) const {
    return {};
  }
};

struct SimpleSettings {
  // The phases' names for messages ("grain y momentum"), [0] the gas; empty or short: "solids m".
  std::vector<std::string> phaseNames;
  Vec3 gravity = Vec3::Zero();
  double pressureRelaxation = 0.8;  // omega_P (MFiX UR_FAC(1))
  // alpha_u. MFiX's default is 0.5; 0.9 converges the grain bed in as many iterations per step
  // at ten times tighter residuals (measured: 15.6 against 15.7 iterations per step).
  double momentumRelaxation = 0.9;
  double fractionRelaxation = 0.5;  // omega_eps of Eq. 3.68
  // eps_p of Eq. 3.68 (the solids fraction of the packed bed); 0: no solids. A model may give each
  // cell its own (FlowModel::packedFractionByCell).
  double packedFraction = 0.0;
  // A cell's solids beyond packedFraction + this is a diverged state, not compaction: the plastic
  // pressure holds a bed within about 0.01 of eps_p (0.603 against 0.596 for the grain bed).
  double overpacking = 0.05;
  double diluteFraction = 1e-4;  // solids faces below this keep only their local momentum terms
  // The normalised residuals' bound. MFiX's TOL_RESID is 1e-3; with that bound the momentum the
  // unconverged remainder leaves in a slugging grain bed shifted its time-averaged pressure
  // balance by 4.6 % of the bed weight, with 1e-4 by 0.2 % (measured, issue 17).
  double tolerance = 1e-4;
  // Momentum residuals are velocity errors over the phase's largest speed, or over this floor
  // where the phase is nearly at rest [m/s].
  double velocityScale = 1e-3;
  // The solids mass Eq. 3.68's relaxation may withhold in a converged step, relative to the
  // phase's inventory: what keeps a long run's mass balance to round-off.
  double massTolerance = 1e-10;
  int maxIterations = 50;
  // MFiX's DETECT_STALL (check_convergence.f, on by default there since 1999): every
  // `stallWindow` iterations past the second window, a step whose largest residual has not fallen
  // below what it was one window earlier gives up, to be retried at a smaller step, instead of
  // running on to maxIterations. A failed step otherwise costs maxIterations iterations: a fifth of
  // all iterations of the Goldschmidt binary bed with rotation (issue 55). 0: off.
  int stallWindow = 0;
  // How each momentum component's system, the gas pressure correction and the solids fraction
  // systems (Eq. 3.69's correction and the step's closing continuity, solveFractionNonNegative)
  // are solved (StencilSystem.hpp).
  LinearSolve momentumSolve;
  LinearSolve pressureSolve;
  LinearSolve fractionSolve;
};

struct StepResult {
  bool converged = false;
  int iterations = 0;
  // The largest normalised residual of the last iteration, its equation ("gas continuity",
  // "solids 1 continuity", "gas x momentum", ...) and the cell (i, j, k) where it is largest.
  double residual = 0.0;
  std::string equation;
  std::array<int, 3> cell{0, 0, 0};
  // A non-finite value or a fraction outside [0, 1] stops the iterations at once; its reason.
  std::string failure;
  // The step gave up on a stalled residual (SimpleSettings::stallWindow) at this iteration; 0 if not.
  int stalledAt = 0;
  // A converged transient step's flow through each boundary patch, per phase (the gas first) and
  // patch [kg/s]: a solids phase's from the fluxes its closing continuity solve moved mass with
  // (so its held mass changes by exactly in - out over the step), the gas's from the state its
  // closing pressure correction leaves (exact too for an incompressible gas; an ideal gas's to the
  // continuity tolerance); a given phase's is zero. Empty otherwise.
  std::vector<std::vector<PatchFlow>> boundaryFlow;
};

// Advances `state` by dt (> 0). `state.time` moves on only when the step converged; otherwise,
// and when an error stops the step, `state` is left as it was. A singular linear system met on
// the way (fluid::SingularSystem) is a step that failed, with its message in `failure`.
StepResult advance(FlowState& state, double dt, const FlowModel& model, const Boundaries& boundaries,
                   const SimpleSettings& settings);

// The same step from the last time level `old` (time, and every fraction and velocity the transient
// terms read) to `state`, which holds the given phases' new fractions and velocities and, for the
// solved phases, the first iterate (usually the last level's values). What a coupled engine calls
// when it has moved the given phases itself: the gas continuity then sees d eps_g / dt of the
// particles. On failure `state` is left as it came in; on success its time is old.time + dt.
StepResult advance(FlowState& state, const FlowState& old, double dt, const FlowModel& model,
                   const Boundaries& boundaries, const SimpleSettings& settings);

// A steady solve (no transient terms), `iterations` outer iterations at most, stopping at the
// tolerance: for flows with a steady state (the laminar channel).
StepResult solveSteady(FlowState& state, const FlowModel& model, const Boundaries& boundaries,
                       const SimpleSettings& settings);

}  // namespace grainbridge::fluid
