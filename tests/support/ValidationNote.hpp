#pragma once
// printf-style formatting for the notes of validation records (ValidationRecord.hpp): the
// measured slope, N, dt and the like. GCC 12 has no <format>; the format attribute lets the
// compiler check the arguments against the format string.
#include <cstdarg>
#include <cstdio>
#include <string>

namespace grainbridge::testing {

[[gnu::format(printf, 1, 2)]] inline std::string formatNote(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string out(n > 0 ? static_cast<std::size_t>(n) : 0u, '\0');
  if (n > 0) std::vsnprintf(out.data(), out.size() + 1, format, args);
  va_end(args);
  return out;
}

}  // namespace grainbridge::testing
