#pragma once
// One stretch of an engine stage's time loop. Most stages have one phase, the run proper, which
// writes frames and series rows; a stage may put phases without output before it (the two-step
// preparation of Section 6.2: shaking, then relaxing). The driver checkpoints and resumes inside
// any phase; the hooks say what a phase changes:
//   enter      once, when the phase starts: changes the engine state, which checkpoints carry
//              (hold particles in place);
//   configure  when the phase starts and again when a run resumes inside it: settings outside
//              the saved state (a wall's vibration);
//   leave      once, when the phase has run all its steps (release held particles, restart the
//              clock for the next phase).
#include <cstdint>
#include <functional>
#include <string>

#include "core/text/NumberText.hpp"

namespace grainbridge::workflows::driver {

struct Phase {
  std::string name;  // "run", "preparation (shaking)": for logs and progress
  std::int64_t steps = 0;
  bool output = false;  // frames (the initial one included), series rows, throughput log
  // The throughput line for a phase without output too, named by the phase (TF-DEM's settling:
  // the same bed's DEM without the gas, which bench/tfdem-bed.sh sets against the run).
  bool timed = false;
  std::function<void()> enter;
  std::function<void()> configure;
  std::function<void()> leave;
};

// Why `frames` frames after the initial one cannot be spread over an output phase of `steps`
// steps, or "": the schedule writes at most one frame a step, so asking for more would give
// fewer, silently. `steps` is worded as the stage counts them: "30 output intervals (duration
// 0.3 s / output_interval 0.01 s)".
inline std::string framesProblem(std::int64_t frames, std::int64_t steps, const std::string& stepsAre) {
  if (frames <= steps) return {};
  return "asks for " + std::to_string(frames) + " frames after the initial one, but the run has " + stepsAre +
         " and writes at most one frame on each: ask for at most " + std::to_string(steps);
}

}  // namespace grainbridge::workflows::driver
