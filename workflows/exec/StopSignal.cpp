#include "workflows/exec/StopSignal.hpp"

#include <unistd.h>
#include <csignal>

namespace grainbridge::workflows::exec {

namespace {
std::atomic<bool> g_stop{false};
std::atomic<int> g_interrupts{0};

extern "C" void onStopSignal(int signo) {
  if (signo == SIGINT && g_interrupts.fetch_add(1) >= 1) {
    std::signal(SIGINT, SIG_DFL);
    ::raise(SIGINT);
  }
  g_stop.store(true);
}
}  // namespace

void installStopHandlers() {
  struct sigaction sa {};
  sa.sa_handler = onStopSignal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGINT, &sa, nullptr);
}

const std::atomic<bool>& stopFlag() { return g_stop; }
void requestStop() { g_stop.store(true); }

}  // namespace grainbridge::workflows::exec
