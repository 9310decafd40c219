#pragma once
// SIGTERM (sent by batch systems before a time limit) and SIGINT (Ctrl-C) set a flag that
// running stages poll: they checkpoint and stop cleanly, and the executor records the instance
// as interrupted instead of losing it. A second SIGINT kills at once.
#include <atomic>

namespace grainbridge::workflows::exec {
void installStopHandlers();
const std::atomic<bool>& stopFlag();
void requestStop();  // as if a signal arrived (tests)
}  // namespace grainbridge::workflows::exec
