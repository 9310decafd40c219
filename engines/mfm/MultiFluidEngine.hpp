#pragma once
// The multi-fluid engine: gas plus M solids continua on a staggered grid (Chapter 3), advanced by
// the modified SIMPLE step of engines/fluid with the adaptive time step. It owns the grid, the
// boundary patches, the state and the model; the mfm stage wires it to the engine driver.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/SimpleStep.hpp"
#include "engines/fluid/TimeStepControl.hpp"
#include "engines/mfm/MultiFluidModel.hpp"

namespace grainbridge::mfm {

struct StepStatistics {
  long steps = 0;       // converged steps
  long retries = 0;     // steps retried at a smaller time step
  long iterations = 0;  // outer iterations over all converged steps
  long retriedIterations = 0;  // outer iterations of the steps that failed and were retried
  double lastDt = 0.0;  // [s]
  double lastResidual = 0.0;
  // A `table` closure's coverage, over converged steps and the cells holding solids (above the
  // dilute fraction): cell-steps, and solids volume-steps, inside every table, and in all.
  long tableCellSteps = 0, coveredCellSteps = 0;
  double tableSolidsSteps = 0.0, coveredSolidsSteps = 0.0;  // [m^3]
  // What crossed each boundary patch since the run began, per phase (the gas first) and patch,
  // in and out apart [kg], summed over the converged steps (fluid::StepResult::boundaryFlow).
  std::vector<std::vector<fluid::PatchFlow>> boundaryMass;
  // Each phase's mass at the run's start [kg]: the balance's held0.
  std::vector<double> initialMass;
};

class MultiFluidEngine {
 public:
  MultiFluidEngine(const core::data::GridGeometry& geometry, std::vector<fluid::BoundaryPatch> patches,
                   MultiFluidParams model, fluid::SimpleSettings settings, fluid::TimeStepLimits limits);

  [[nodiscard]] const fluid::StaggeredGrid& grid() const { return *grid_; }
  [[nodiscard]] const fluid::Boundaries& boundaries() const { return *boundaries_; }
  [[nodiscard]] fluid::FlowState& state() { return *state_; }
  [[nodiscard]] const fluid::FlowState& state() const { return *state_; }
  [[nodiscard]] const MultiFluidModel& model() const { return model_; }
  [[nodiscard]] const fluid::SimpleSettings& settings() const { return settings_; }
  [[nodiscard]] double time() const { return state_->time; }
  [[nodiscard]] const StepStatistics& statistics() const { return stats_; }
  [[nodiscard]] fluid::TimeStepControl& timeStep() { return control_; }
  [[nodiscard]] const fluid::TimeStepControl& timeStep() const { return control_; }
  void restoreStatistics(const StepStatistics& s) { stats_ = s; }
  // Each phase's mass in the domain now, the gas first [kg] (the gas at each cell's pressure).
  [[nodiscard]] std::vector<double> heldMass() const;
  // Starts the boundary bookkeeping at the current state: held0 from heldMass(), nothing crossed.
  void startMassAccount();
  // Called with a line saying why a step is retried at a smaller one (the stage logs it).
  void onRetry(std::function<void(const std::string&)> log) { onRetry_ = std::move(log); }

  // Takes one converged step (retrying at smaller steps as needed) without passing `limit`.
  // Throws grainbridge::Error naming the time, the equation, the cell and the residual (or the
  // bad value) when no step above the minimum converges; the state stays at the last good level.
  void step(double limit);
  // Steps until time() reaches `time`.
  void advanceTo(double time);

 private:
  [[nodiscard]] double speedOverSpacing() const;
  // Adds the converged state's cells to the table coverage counts.
  void countCoverage();
  // Adds a converged step's boundary flows (rates [kg/s] over dt) to the account.
  void accountBoundaryFlow(const std::vector<std::vector<fluid::PatchFlow>>& rates, double dt);

  std::unique_ptr<fluid::StaggeredGrid> grid_;
  std::unique_ptr<fluid::Boundaries> boundaries_;
  std::unique_ptr<fluid::FlowState> state_;
  MultiFluidModel model_;
  fluid::SimpleSettings settings_;
  fluid::TimeStepControl control_;
  StepStatistics stats_;
  std::function<void(const std::string&)> onRetry_;
};

}  // namespace grainbridge::mfm
