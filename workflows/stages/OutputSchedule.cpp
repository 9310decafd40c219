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

RunSchedule readRunSchedule(const nlohmann::json& p, std::vector<core::engine::SetupProblem>& problems) {
  RunSchedule s;
  s.duration = p.at("duration");
  s.outputInterval = p.at("output_interval");
  s.averageFrom = p.at("average_from");
  s.averageTo = p.contains("average_to") ? p.at("average_to").get<double>() : s.duration;
  if (s.averageFrom >= s.duration)
    problems.push_back({"/average_from", "must be before the end of the run (duration)"});
  if (s.averageTo > s.duration * (1.0 + 1e-12))
    problems.push_back({"/average_to", "is after the end of the run (duration)"});
  if (s.averageTo <= s.averageFrom) problems.push_back({"/average_to", "must be after average_from"});
  if (s.outputInterval > s.duration) problems.push_back({"/output_interval", "is longer than the run (duration)"});
  return s;
}

}  // namespace grainbridge::workflows::stages
