#include "core/FailPoint.hpp"

#include <unistd.h>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <string>

namespace grainbridge::core {

namespace {
struct Armed {
  std::string name;  // empty: no fail point armed
  long hit = 1;      // kill on this hit of `name` (GRAINBRIDGE_FAILPOINT=name:hit)
};

const Armed& armed() {
  static const Armed a = [] {
    Armed out;
    const char* env = std::getenv("GRAINBRIDGE_FAILPOINT");
    if (env == nullptr) return out;
    std::string s(env);
    const auto colon = s.rfind(':');
    if (colon != std::string::npos) {
      out.hit = std::max(1L, std::strtol(s.c_str() + colon + 1, nullptr, 10));
      s.resize(colon);
    }
    out.name = s;
    return out;
  }();
  return a;
}
}  // namespace

void failPoint(std::string_view name) {
  const Armed& a = armed();
  if (a.name.empty() || name != a.name) return;
  static std::atomic<long> hits{0};
  if (++hits == a.hit) ::kill(::getpid(), SIGKILL);
}

}  // namespace grainbridge::core
