#pragma once
// The adaptive time step of the multiphase solver, as MFiX adjusts DT: a step that converged in
// few outer iterations lets the next one grow, one that needed many makes it shrink, a step that
// did not converge is retried at half the step, and the CFL number of the fastest phase caps it.
// Only below the minimum step does the run stop. The controller's state (the current step) goes
// into checkpoints, so a resumed run takes the steps the uninterrupted one takes.
#include <vector>

#include "core/engine/SetupProblem.hpp"

namespace grainbridge::fluid {

struct TimeStepLimits {
  double initial = 1e-4;  // [s]
  double minimum = 1e-7;  // [s]: below this a non-converging step stops the run
  double maximum = 1e-3;  // [s] (MFiX DT_MAX of VALIDATION.md's Goldschmidt runs)
  double courant = 0.5;   // largest |v| dt / dx of any phase on any face
  // The iteration band: measured on the grain bed at the solver's default tolerance, a fixed step
  // of 1e-4 s converges in 13.8 iterations, 3e-4 s in 17.1, 6e-4 s in 20 (3.2 times less work
  // per simulated second than 1e-4 s), and 1e-3 s stalls on the packed cells.
  int fewIterations = 20;   // converged in at most this many: grow by `growth`
  int manyIterations = 35;  // converged in more: shrink by `shrink`
  double growth = 1.05;
  double shrink = 0.9;
  // Why these limits cannot be used, each at the pointer of its key in the fluid set-up's JSON
  // form (dt, dt_min; fluid/FluidSetup.hpp); empty when they can.
  [[nodiscard]] std::vector<core::engine::SetupProblem> problems() const;
};

class TimeStepControl {
 public:
  explicit TimeStepControl(TimeStepLimits limits) : limits_(limits), dt_(limits.initial) {}

  [[nodiscard]] const TimeStepLimits& limits() const { return limits_; }
  // The step to try next, capped by the CFL limit for the fastest face speed over its spacing
  // `speedOverSpacing` = max |v| / dx [1/s] (0: no cap).
  [[nodiscard]] double next(double speedOverSpacing) const;
  // After a converged step that took `iterations` outer iterations.
  void converged(int iterations);
  // After a step of `tried` seconds failed: the next try is half of it; false when that would fall
  // below the minimum.
  [[nodiscard]] bool failed(double tried);

  [[nodiscard]] double current() const { return dt_; }
  void restore(double dt) { dt_ = dt; }  // from a checkpoint

 private:
  TimeStepLimits limits_;
  double dt_;
};

}  // namespace grainbridge::fluid
