#include "workflows/stages/MfmSeriesColumns.hpp"

#include <spdlog/spdlog.h>

#include "core/text/NumberText.hpp"
#include "engines/fluid/BedMeasures.hpp"

namespace grainbridge::workflows::stages {

MfmSeriesColumns::MfmSeriesColumns(const mfm::MfmEngine& engine, const MfmSetup& setup, std::string stage)
    : engine_(engine), setup_(setup), stage_(std::move(stage)) {
  for (const auto& tap : setup.taps) names_.push_back("dp_" + tap.name);
  for (const auto& s : setup.engine.model.solids) names_.push_back("mean_height_" + s.name);
  for (const auto& s : setup.engine.model.solids) names_.push_back("solids_volume_" + s.name);
  // The solver's history: its last step, and its step and iteration counts so far (differences
  // of two rows give the iterations per step over an interval), the last step's worst residual.
  for (const char* n : {"dt", "solver_steps", "iterations", "residual"}) names_.push_back(n);
  if (setup.segregation) names_.push_back("segregation_percentage");
}

void MfmSeriesColumns::sample(driver::SeriesRow& row) {
  const auto& state = engine_.engine().state();
  const fluid::VerticalAxis vertical = fluid::verticalAxis(setup_.engine.settings.gravity);
  std::vector<double> values;
  for (const auto& tap : setup_.taps) {
    values.push_back(fluid::pressureAtHeight(state, vertical, tap.low) -
                     fluid::pressureAtHeight(state, vertical, tap.high));
  }
  const std::size_t M = setup_.engine.model.solids.size();
  for (std::size_t m = 1; m <= M; ++m) values.push_back(fluid::meanParticleHeight(state, vertical, m));
  for (std::size_t m = 1; m <= M; ++m) values.push_back(fluid::solidsVolume(state, m));
  const auto& stats = engine_.engine().statistics();
  values.push_back(stats.lastDt);
  values.push_back(static_cast<double>(stats.steps));
  values.push_back(static_cast<double>(stats.iterations));
  values.push_back(stats.lastResidual);
  if (const auto& seg = setup_.segregation) {
    values.push_back(fluid::segregationPercentage(values[setup_.taps.size() + seg->small],
                                                  values[setup_.taps.size() + seg->large], seg->smallShare));
  }
  for (double v : values) row.add(v);
  // The residual history in the log, ten lines over the run: what the solver needed since the
  // last line (steps, iterations per step, retries) and where it stands.
  if (state.time >= nextLog_ - 1e-9 * setup_.engine.interval) {
    const long steps = stats.steps - lastSteps_, iterations = stats.iterations - lastIterations_;
    spdlog::info(
        "{}: t = {} s, dt = {} s, {} steps since the last line at {} iterations per step, {} retried, last "
        "residual {}",
        stage_, core::humanNumber(state.time), core::humanNumber(stats.lastDt, 3), steps,
        core::humanNumber(steps > 0 ? static_cast<double>(iterations) / steps : 0.0, 3), stats.retries - lastRetries_,
        core::humanNumber(stats.lastResidual, 2));
    lastSteps_ = stats.steps;
    lastIterations_ = stats.iterations;
    lastRetries_ = stats.retries;
    nextLog_ = state.time + 0.1 * setup_.duration;
  }
  // The window: from average_from on (to round-off in the sampling times).
  if (state.time >= setup_.averageFrom - 1e-9 * setup_.engine.interval) {
    for (std::size_t k = 0; k < names_.size(); ++k) window_[names_[k]].push_back(values[k]);
    fields_.add(engine_.frame());
  }
}

}  // namespace grainbridge::workflows::stages
