#pragma once
// The series schedule of the continuum engine stages (mfm, tfdem): a row every `output_interval`
// of simulated time from the start, the last one at the end of the run. That holds only when
// `duration` is a whole number of intervals: otherwise the rows are spread over the run at
// another spacing than the one asked (a 0.0142 s interval over 0.1 s gave rows 0.0125 s apart),
// and whatever reads them at the nominal interval (the pressure drop's dominant frequency) is off
// by the ratio. The stages refuse such an interval at `grainbridge check`, with one rule here.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/engine/SetupProblem.hpp"

namespace grainbridge::workflows::stages {

// Whether `ratio` is a whole number (>= 1) to 1e-9 of itself: round-off in the resolved values,
// never a real remainder.
[[nodiscard]] bool wholeNumberOfIntervals(double ratio);

// Why `interval` cannot sample a run of `duration` evenly, with a fix, or "" when it can: "0.0142
// s does not divide duration 0.1 s (7.04 intervals); use a divisor such as 0.0125 s". With a fixed
// step (`step` > 0, tfdem's gas step, named `stepName`) the divisor offered is a whole number of
// steps too, and when none is (a duration not itself a whole number of steps) a duration is
// offered instead. An interval above the duration is the caller's other message.
[[nodiscard]] std::string outputIntervalProblem(double interval, double duration, double step = 0.0,
                                                const std::string& stepName = "");

// The run's length, its series interval and its averaging window as the continuum stages write
// them: duration, output_interval, average_from, average_to (default: the duration).
struct RunSchedule {
  double duration = 0.0;
  double outputInterval = 0.0;
  double averageFrom = 0.0;
  double averageTo = 0.0;
};

// The schedule of resolved params `p`, with what makes it unusable appended to `problems`
// (pointers below /params): a window not inside the run or empty, an interval longer than the run.
[[nodiscard]] RunSchedule readRunSchedule(const nlohmann::json& p, std::vector<core::engine::SetupProblem>& problems);

}  // namespace grainbridge::workflows::stages
