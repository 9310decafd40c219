#include "engines/mfm/MultiFluidEngine.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"

namespace grainbridge::mfm {

namespace {

// Whether a failed step's message already names its cell: a singular system's does (the solver's
// zero pivot, fluid::StencilSystem), and the step's own cell would be a residual's that no
// iteration set.
bool namesItsCell(const fluid::StepResult& r) { return r.failure.find(" at cell (") != std::string::npos; }

}  // namespace

MultiFluidEngine::MultiFluidEngine(const core::data::GridGeometry& geometry, std::vector<fluid::BoundaryPatch> patches,
                                   MultiFluidParams model, fluid::SimpleSettings settings, fluid::TimeStepLimits limits)
    : grid_(std::make_unique<fluid::StaggeredGrid>(geometry)),
      model_(std::move(model)),
      settings_(settings),
      control_(limits) {
  const std::size_t phases = 1 + model_.params().solids.size();
  boundaries_ = std::make_unique<fluid::Boundaries>(*grid_, std::move(patches), phases);
  state_ = std::make_unique<fluid::FlowState>(*grid_, phases);
  for (std::size_t c = 0; c < grid_->paddedCount(); ++c) state_->phases[0].fraction[c] = 1.0;
}

double MultiFluidEngine::speedOverSpacing() const {
  double worst = 0.0;
  for (const auto& phase : state_->phases) {
    for (int a = 0; a < grid_->dimensions(); ++a) {
      const auto& v = phase.velocity[static_cast<std::size_t>(a)].values();
      for (double u : v) worst = std::max(worst, std::abs(u) / grid_->spacing(a));
    }
  }
  return worst;
}

void MultiFluidEngine::step(double limit) {
  for (;;) {
    const double dt = std::min(control_.next(speedOverSpacing()), limit - state_->time);
    // A step that cannot be retried (half of it below the minimum) runs to maxIterations, as MFiX
    // forces the iterations at DT_MIN.
    fluid::SimpleSettings settings = settings_;
    if (dt * 0.5 < control_.limits().minimum) settings.stallWindow = 0;
    const fluid::StepResult r = fluid::advance(*state_, dt, model_, *boundaries_, settings);
    if (r.converged) {
      control_.converged(r.iterations);
      ++stats_.steps;
      stats_.iterations += r.iterations;
      stats_.lastDt = dt;
      stats_.lastResidual = r.residual;
      accountBoundaryFlow(r.boundaryFlow, dt);
      if (model_.params().closure.kind() == "table") countCoverage();
      return;
    }
    ++stats_.retries;
    stats_.retriedIterations += r.iterations;
    const bool retry = control_.failed(dt);
    if (retry && onRetry_) {
      std::ostringstream msg;
      msg << "t = " << state_->time << " s: the step of " << dt << " s did not converge ("
          << (r.failure.empty() ? "the " + r.equation + " residual " + std::to_string(r.residual) : r.failure);
      if (r.stalledAt > 0) msg << ", stalled at iteration " << r.stalledAt;
      // The step's cell (the worst residual's, or the bad iterate's); a singular system names its own.
      if (!namesItsCell(r)) msg << ", cell (" << r.cell[0] << ", " << r.cell[1] << ", " << r.cell[2] << ")";
      msg << "); retrying with " << control_.current() << " s";
      onRetry_(msg.str());
    }
    if (!retry) {
      std::ostringstream msg;
      msg << "mfm: at t = " << state_->time << " s no step down to the minimum " << control_.limits().minimum
          << " s converged; at dt = " << dt << " s ";
      if (!r.failure.empty()) {
        msg << r.failure;
      } else {
        msg << "the " << r.equation << " residual stayed at " << r.residual << " (tolerance " << settings_.tolerance
            << ") after " << r.iterations << " iterations";
      }
      if (!namesItsCell(r)) msg << ", cell (" << r.cell[0] << ", " << r.cell[1] << ", " << r.cell[2] << ")";
      throw Error(msg.str());
    }
  }
}

std::vector<double> MultiFluidEngine::heldMass() const {
  const std::size_t phases = state_->phases.size();
  std::vector<double> held(phases, 0.0);
  fluid::CellField gasDensity(*grid_, 0.0);
  for (std::size_t c = 0; c < grid_->paddedCount(); ++c)
    gasDensity[c] = model_.params().gas.densityAt(state_->pressure[c]);
  held[0] = fluid::heldMass(state_->phases[0].fraction, gasDensity);
  for (std::size_t m = 1; m < phases; ++m) {
    const fluid::CellField density(*grid_, model_.params().solids[m - 1].density);
    held[m] = fluid::heldMass(state_->phases[m].fraction, density);
  }
  return held;
}

void MultiFluidEngine::startMassAccount() {
  stats_.initialMass = heldMass();
  stats_.boundaryMass.assign(state_->phases.size(), std::vector<fluid::PatchFlow>(boundaries_->patches().size()));
}

void MultiFluidEngine::accountBoundaryFlow(const std::vector<std::vector<fluid::PatchFlow>>& rates, double dt) {
  if (stats_.boundaryMass.size() != rates.size()) return;  // no account started
  for (std::size_t m = 0; m < rates.size(); ++m) {
    for (std::size_t p = 0; p < rates[m].size(); ++p) {
      stats_.boundaryMass[m][p].in += rates[m][p].in * dt;
      stats_.boundaryMass[m][p].out += rates[m][p].out * dt;
    }
  }
}

void MultiFluidEngine::countCoverage() {
  const double volume = grid_->cellVolume();
  for (int k = 0; k < grid_->cells(2); ++k) {
    for (int j = 0; j < grid_->cells(1); ++j) {
      for (int i = 0; i < grid_->cells(0); ++i) {
        const std::size_t c = grid_->index(i, j, k);
        for (std::size_t m = 1; m < state_->phases.size(); ++m) {
          const double eps = state_->phases[m].fraction[c];
          if (eps < settings_.diluteFraction) continue;
          const bool covered = model_.tableCovers(*state_, m, c);
          ++stats_.tableCellSteps;
          stats_.tableSolidsSteps += eps * volume;
          if (covered) {
            ++stats_.coveredCellSteps;
            stats_.coveredSolidsSteps += eps * volume;
          }
        }
      }
    }
  }
}

void MultiFluidEngine::advanceTo(double time) {
  // A remainder below a thousandth of the minimum step is round-off in the step sum.
  while (state_->time < time - 1e-3 * control_.limits().minimum) step(time);
}

}  // namespace grainbridge::mfm
