#pragma once
// Logging goes through spdlog. The CLI sets the level once (--verbose / --quiet); worker MPI
// ranks prefix their rank so interleaved lines stay attributable.
#include <spdlog/spdlog.h>

namespace grainbridge::core {
enum class Verbosity { Quiet, Normal, Verbose };
void initLogging(Verbosity verbosity, int rank = 0);
}  // namespace grainbridge::core
