#include "workflows/stages/OutputSchedule.hpp"

#include <cmath>

#include "core/text/NumberText.hpp"

namespace grainbridge::workflows::stages {

bool wholeNumberOfIntervals(double ratio) {
  return std::llround(ratio) >= 1 && std::abs(ratio - std::round(ratio)) <= 1e-9 * ratio;
}

std::string outputIntervalProblem(double interval, double duration, double step, const std::string& stepName) {
  const double ratio = duration / interval;
  if (ratio < 1.0 || wholeNumberOfIntervals(ratio)) return {};
  using core::humanNumber;
  std::string why = humanNumber(interval) + " s does not divide duration " + humanNumber(duration) + " s (" +
                    humanNumber(ratio, 3) + " intervals)";
  // The divisor nearest below the interval asked (never sparser rows than asked): duration / n for
  // the fewest intervals n above the ratio, which with a fixed step must also be whole steps, i.e.
  // n must divide the run's steps. A duration offered instead is that many intervals: never a
  // shorter run than asked (a window ending at the duration asked still fits).
  const auto fewest = static_cast<std::int64_t>(std::ceil(ratio));
  if (step <= 0.0) return why + "; use a divisor such as " + humanNumber(duration / static_cast<double>(fewest)) + " s";
  const double steps = duration / step;
  if (wholeNumberOfIntervals(steps)) {
    const std::int64_t total = std::llround(steps);
    for (std::int64_t n = fewest; n <= total; ++n) {
      if (total % n == 0) {
        return why + "; use a divisor that is a whole number of " + stepName + " = " + humanNumber(step) +
               " s, such as " + humanNumber(duration / static_cast<double>(n)) + " s";
      }
    }
  }
  return why + "; no divisor is a whole number of " + stepName + " = " + humanNumber(step) +
         " s: use a duration such as " + humanNumber(static_cast<double>(fewest) * interval) + " s (" +
         std::to_string(fewest) + " intervals)";
}

}  // namespace grainbridge::workflows::stages
