#include "engines/fluid/TimeStepControl.hpp"

#include <algorithm>

#include "core/text/NumberText.hpp"

namespace grainbridge::fluid {

std::vector<core::engine::SetupProblem> TimeStepLimits::problems() const {
  std::vector<core::engine::SetupProblem> out;
  if (!(minimum > 0.0)) {
    out.push_back({"/dt", "the minimum time step must be positive"});
  } else if (!(maximum >= minimum)) {
    out.push_back({"/dt_min", "dt_min = " + core::humanNumber(minimum) +
                                  " s is above dt_max = " + core::humanNumber(maximum) +
                                  " s: the smallest step must not exceed the largest (equal: a fixed step)"});
  } else if (!(initial >= minimum && initial <= maximum)) {
    out.push_back({"/dt", "the initial time step must lie between the minimum and the maximum"});
  }
  if (!(courant > 0.0)) out.push_back({"/dt", "the Courant number must be positive"});
  if (!(growth >= 1.0) || !(shrink > 0.0 && shrink <= 1.0))
    out.push_back({"/dt", "growth must be >= 1 and shrink in (0, 1]"});
  if (fewIterations < 1 || manyIterations < fewIterations)
    out.push_back({"/dt", "need 1 <= few iterations <= many iterations"});
  return out;
}

double TimeStepControl::next(double speedOverSpacing) const {
  double dt = dt_;
  if (speedOverSpacing > 0.0) dt = std::min(dt, limits_.courant / speedOverSpacing);
  return std::max(dt, limits_.minimum);
}

void TimeStepControl::converged(int iterations) {
  if (iterations <= limits_.fewIterations) dt_ = std::min(dt_ * limits_.growth, limits_.maximum);
  if (iterations > limits_.manyIterations) dt_ = std::max(dt_ * limits_.shrink, limits_.minimum);
}

bool TimeStepControl::failed(double tried) {
  if (tried * 0.5 < limits_.minimum) return false;
  dt_ = tried * 0.5;
  return true;
}

}  // namespace grainbridge::fluid
