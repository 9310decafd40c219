#include "core/Log.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>

namespace grainbridge::core {
void initLogging(Verbosity verbosity, int rank) {
  // Logs go to stderr so stdout stays clean for machine-readable output (db query --format csv).
  auto logger = spdlog::stderr_color_mt("grainbridge");
  spdlog::set_default_logger(logger);
  const std::string rankTag = rank > 0 ? "[rank " + std::to_string(rank) + "] " : "";
  spdlog::set_pattern("[%H:%M:%S] [%^%l%$] " + rankTag + "%v");
  switch (verbosity) {
    case Verbosity::Quiet:
      spdlog::set_level(spdlog::level::warn);
      break;
    case Verbosity::Normal:
      spdlog::set_level(spdlog::level::info);
      break;
    case Verbosity::Verbose:
      spdlog::set_level(spdlog::level::debug);
      break;
  }
}
}  // namespace grainbridge::core
