#pragma once
// The pressure taps' part of a bed stage's summary (mfm, tfdem), written once so that what a
// stage records and what its plannedOutput promises to comparing stages (bed_compare,
// fluidization, report) cannot drift apart between the engines.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "workflows/stages/FluidSchema.hpp"
#include "workflows/stages/PlannedOutput.hpp"

namespace grainbridge::workflows::stages {

// Per tap: dp_<tap> averaged over the window (with its _err), its dominant frequency and
// amplitude (dp_<tap>_frequency, dp_<tap>_amplitude; Fig. 7.3) at `times`, the window's rows'
// own times; the first tap's drop again as pressure_drop, and that tap's name as
// pressure_drop_tap. `window` holds the column dp_<tap> of every tap.
void addTapSummary(nlohmann::json& summary, const std::vector<PressureTap>& taps,
                   const std::map<std::string, std::vector<double>>& window, const std::vector<double>& times);

// The summary keys and series columns of the params' pressure_taps that addTapSummary and the
// stage's series.csv give: pressure_drop and pressure_drop_tap (given any tap), dp_<tap>.
void addTapPlannedOutput(PlannedOutput& out, const nlohmann::json& params);

}  // namespace grainbridge::workflows::stages
