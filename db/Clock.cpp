#include "db/Clock.hpp"

#include <cstdio>

namespace grainbridge::db {

namespace {
constexpr std::size_t kTimestampLength = 24;  // "YYYY-MM-DDTHH:MM:SS.mmmZ"
}

std::string nowUtc() { return formatUtc(std::chrono::system_clock::now()); }

std::string formatUtc(std::chrono::system_clock::time_point time) {
  using namespace std::chrono;
  // Calendar arithmetic in <chrono> avoids gmtime's static buffer and the time zone database.
  const auto ms = floor<milliseconds>(time);
  const auto day = floor<days>(ms);
  const year_month_day ymd{day};
  const hh_mm_ss<milliseconds> tod{ms - day};
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%04d-%02u-%02uT%02d:%02d:%02d.%03dZ", static_cast<int>(ymd.year()),
                static_cast<unsigned>(ymd.month()), static_cast<unsigned>(ymd.day()),
                static_cast<int>(tod.hours().count()), static_cast<int>(tod.minutes().count()),
                static_cast<int>(tod.seconds().count()), static_cast<int>(tod.subseconds().count()));
  return buffer;
}

std::optional<std::chrono::system_clock::time_point> parseUtc(const std::string& text) {
  using namespace std::chrono;
  if (text.size() != kTimestampLength) return std::nullopt;
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, s = 0, msec = 0;
  char zulu = 0;
  if (std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d:%2d.%3d%c", &y, &mo, &d, &h, &mi, &s, &msec, &zulu) != 8 ||
      zulu != 'Z')
    return std::nullopt;
  const year_month_day ymd{year{y}, month{static_cast<unsigned>(mo)}, day{static_cast<unsigned>(d)}};
  if (!ymd.ok() || h < 0 || h > 23 || mi < 0 || mi > 59 || s < 0 || s > 60 || msec < 0) return std::nullopt;
  return system_clock::time_point{sys_days{ymd} + hours{h} + minutes{mi} + seconds{s} + milliseconds{msec}};
}

}  // namespace grainbridge::db
