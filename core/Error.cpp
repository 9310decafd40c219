#include "core/Error.hpp"

#include <cstdio>
#include <cstdlib>

#include "core/parallel/Communicator.hpp"

namespace grainbridge::detail {
void assertionFailed(const char* expr, const char* file, int line, const std::string& msg) {
  std::fprintf(stderr, "grainbridge: internal error on rank %d at %s:%d: assertion '%s' failed: %s\n",
               core::parallel::worldRank(), file, line, expr, msg.c_str());
  std::fflush(stderr);
  std::abort();
}
}  // namespace grainbridge::detail
