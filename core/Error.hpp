#pragma once
// Two error channels (STYLE.md 7):
//  - grainbridge::Error: user or input errors. The message names what is wrong, where
//    (JSON pointer, file, value) and, where possible, the fix. Context is prepended as the
//    error travels up ("while loading frame x.h5: ...").
//  - GB_ASSERT: programmer errors. Prints file, line and MPI rank, then aborts.
#include <stdexcept>
#include <string>

namespace grainbridge {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
  // Returns a copy whose message is "<context>: <original message>".
  [[nodiscard]] Error withContext(const std::string& context) const { return Error(context + ": " + what()); }
};

namespace detail {
[[noreturn]] void assertionFailed(const char* expr, const char* file, int line, const std::string& msg);
}
}  // namespace grainbridge

#define GB_ASSERT(cond, msg)                                                               \
  do {                                                                                     \
    if (!(cond)) ::grainbridge::detail::assertionFailed(#cond, __FILE__, __LINE__, (msg)); \
  } while (false)
