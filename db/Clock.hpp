#pragma once
// Timestamps in the database are TEXT in ISO-8601 UTC with milliseconds
// ("2026-11-23T20:14:05.123Z"): readable in the sqlite3 shell and pandas, independent of the
// host's time zone, and with a fixed width so string order is time order (SQL can compare
// them directly).
#include <chrono>
#include <optional>
#include <string>

namespace grainbridge::db {

std::string nowUtc();
std::string formatUtc(std::chrono::system_clock::time_point time);
// Inverse of formatUtc; nullopt when the text is not in exactly that format.
std::optional<std::chrono::system_clock::time_point> parseUtc(const std::string& text);

}  // namespace grainbridge::db
