#pragma once
// Progress of a long stage: percent, rate and ETA. On a terminal it redraws one status line;
// otherwise (batch jobs, CI logs) it writes a plain log line at most every `logInterval`
// seconds, so a log file stays readable.
#include <chrono>
#include <string>

namespace grainbridge::core {

class Progress {
 public:
  // `unit` names what is counted ("steps", "frames"). `alreadyDone` is where a resumed run
  // starts: the rate and ETA count only the work done since, not the checkpointed part.
  Progress(std::string label, double total, std::string unit, double logIntervalSeconds = 10.0,
           double alreadyDone = 0.0);
  void update(double done);
  void finish();

 private:
  std::string line(double done, double elapsed) const;

  std::string label_;
  double total_;
  std::string unit_;
  double logInterval_;
  double startDone_;
  bool terminal_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastShown_;
};

}  // namespace grainbridge::core
