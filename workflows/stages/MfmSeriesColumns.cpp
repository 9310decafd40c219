#include "workflows/stages/MfmSeriesColumns.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "core/text/NumberText.hpp"
#include "engines/fluid/BedMeasures.hpp"
#include "engines/fluid/BoundaryFlow.hpp"
#include "engines/fluid/FluidSetup.hpp"

namespace grainbridge::workflows::stages {

std::vector<std::string> outletLabels(const std::vector<std::string>& outletSides) {
  std::vector<std::string> labels(outletSides.size());
  for (std::size_t k = 0; k < outletSides.size(); ++k) {
    if (outletSides[k].empty()) continue;
    const auto shared = std::count(outletSides.begin(), outletSides.end(), outletSides[k]);
    labels[k] = shared > 1 ? outletSides[k] + "_" + std::to_string(k) : outletSides[k];
  }
  return labels;
}

std::vector<std::string> massAccountColumns(const std::vector<std::string>& phases,
                                            const std::vector<std::string>& outletSides) {
  std::vector<std::string> names;
  const auto labels = outletLabels(outletSides);
  for (const auto& phase : phases) {
    names.push_back("mass_" + phase);
    names.push_back("mass_in_" + phase);
    names.push_back("mass_out_" + phase);
    for (const auto& label : labels) {
      if (!label.empty()) names.push_back("mass_out_" + phase + "_" + label);
    }
  }
  return names;
}

namespace {

std::vector<std::string> outletSidesOf(const std::vector<fluid::BoundaryPatch>& patches) {
  std::vector<std::string> out;
  for (const auto& patch : patches)
    out.emplace_back(patch.kind == fluid::BoundaryKind::PressureOutlet ? fluid::sideKey(patch.side) : "");
  return out;
}

std::vector<std::string> phaseNames(const MfmSetup& setup) {
  std::vector<std::string> names{"gas"};
  for (const auto& s : setup.engine.model.solids) names.push_back(s.name);
  return names;
}

}  // namespace

MfmSeriesColumns::MfmSeriesColumns(const mfm::MfmEngine& engine, const MfmSetup& setup, std::string stage)
    : engine_(engine), setup_(setup), stage_(std::move(stage)) {
  for (const auto& tap : setup.taps) names_.push_back("dp_" + tap.name);
  for (const auto& s : setup.engine.model.solids) names_.push_back("mean_height_" + s.name);
  for (const auto& s : setup.engine.model.solids) names_.push_back("solids_volume_" + s.name);
  // The solver's history: its last step, and its step and iteration counts so far (differences
  // of two rows give the iterations per step over an interval), the last step's worst residual.
  for (const char* n : {"dt", "solver_steps", "iterations", "residual"}) names_.push_back(n);
  if (setup.segregation) names_.push_back("segregation_percentage");
  // Where the bed packs and how agitated each phase is (issue 55: what decides segregation).
  names_.push_back("plastic_solids_share");
  if (setup.engine.model.granularEnergy == mfm::GranularEnergyForm::Pde) {
    for (const auto& s : setup.engine.model.solids) names_.push_back("theta_" + s.name);
  }
  const auto sides = outletSidesOf(setup.engine.patches);
  for (std::size_t k = 0; k < sides.size(); ++k) {
    if (!sides[k].empty()) outlets_.push_back(k);
  }
  for (auto& name : massAccountColumns(phaseNames(setup), sides)) names_.push_back(std::move(name));
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
  values.push_back(engine_.engine().model().plasticSolidsShare(state));
  if (setup_.engine.model.granularEnergy == mfm::GranularEnergyForm::Pde) {
    for (std::size_t m = 1; m <= M; ++m) values.push_back(fluid::meanGranularTemperature(state, m));
  }
  const auto held = engine_.engine().heldMass();
  for (std::size_t m = 0; m < held.size(); ++m) {
    const fluid::PatchFlow crossed = fluid::total(stats.boundaryMass[m]);
    values.push_back(held[m]);
    values.push_back(crossed.in);
    values.push_back(crossed.out);
    for (const std::size_t k : outlets_) values.push_back(stats.boundaryMass[m][k].out);
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
    nextLog_ = state.time + 0.1 * setup_.schedule.duration;
  }
  // The window: from average_from to average_to (to round-off in the sampling times).
  const double slack = 1e-9 * setup_.engine.interval;
  if (state.time >= setup_.schedule.averageFrom - slack && state.time <= setup_.schedule.averageTo + slack) {
    for (std::size_t k = 0; k < names_.size(); ++k) window_[names_[k]].push_back(values[k]);
    windowTimes_.push_back(state.time);
    fields_.add(engine_.frame());
  }
}

}  // namespace grainbridge::workflows::stages
