#include "core/Progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "core/Log.hpp"
#include "core/text/NumberText.hpp"

namespace grainbridge::core {

namespace {
std::string formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--:--";
  const long s = std::lround(seconds);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}
}  // namespace

Progress::Progress(std::string label, double total, std::string unit, double logIntervalSeconds, double alreadyDone)
    : label_(std::move(label)),
      total_(total),
      unit_(std::move(unit)),
      logInterval_(logIntervalSeconds),
      startDone_(alreadyDone),
      terminal_(::isatty(STDERR_FILENO) != 0 && spdlog::get_level() <= spdlog::level::info),
      start_(std::chrono::steady_clock::now()),
      lastShown_(start_) {}

std::string Progress::line(double done, double elapsed) const {
  const double fraction = total_ > 0 ? done / total_ : 0.0;
  const double rate = elapsed > 0 ? (done - startDone_) / elapsed : 0.0;
  const double eta = rate > 0 ? (total_ - done) / rate : NAN;
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s: %5.1f%%  %s %s/s  elapsed %s  ETA %s", label_.c_str(), 100.0 * fraction,
                humanNumber(rate, 3).c_str(), unit_.c_str(), formatDuration(elapsed).c_str(), formatDuration(eta).c_str());
  return buf;
}

void Progress::update(double done) {
  const auto now = std::chrono::steady_clock::now();
  const double sinceShown = std::chrono::duration<double>(now - lastShown_).count();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (terminal_) {
    if (sinceShown < 0.2) return;  // redraw at most 5 times a second
    std::fprintf(stderr, "\r\033[K%s", line(done, elapsed).c_str());
    std::fflush(stderr);
  } else {
    if (sinceShown < logInterval_) return;
    spdlog::info("{}", line(done, elapsed));
  }
  lastShown_ = now;
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (terminal_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
  }
}

}  // namespace grainbridge::core
