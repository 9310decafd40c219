#pragma once
// A stage key counts as done only if its completed record is intact: the run is marked done,
// its folder and manifest exist, and every artifact still has the recorded sha256.
#include <filesystem>
#include <optional>
#include <string>

#include "db/Database.hpp"
#include "db/Records.hpp"

namespace grainbridge::workflows::exec {
std::optional<db::CacheEntry> validCacheEntry(db::Database& database, const std::filesystem::path& resultsRoot,
                                              const std::string& key, std::string* whyNot = nullptr);
}  // namespace grainbridge::workflows::exec
