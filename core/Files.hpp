#pragma once
// File helpers that keep the "a crash loses nothing already written" promise: a file is
// written beside its destination, flushed to disk and renamed over it, so readers see either
// the old or the new content, never half of one.
#include <filesystem>
#include <string_view>

namespace grainbridge::core {
void writeFileAtomically(const std::filesystem::path& path, std::string_view content);
// fsync on a directory, so a rename inside it survives a crash.
void syncDirectory(const std::filesystem::path& dir);
std::string readFile(const std::filesystem::path& path);
}  // namespace grainbridge::core
