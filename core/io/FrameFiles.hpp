#pragma once
// Naming, listing and publishing of per-frame files under `<directory>/frames/`. A frame is
// written to `<name>.tmp` beside its final name, flushed, and renamed into place, so a kill
// mid-write leaves at most a stray .tmp file and never damages a published frame
// (DESIGN.md "Data contracts").
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace grainbridge::core::io {

// "<prefix>_<step zero-padded to 9 digits>.h5"; steps beyond 9 digits just get longer.
std::string frameFileName(std::string_view prefix, std::int64_t step);

// Published frames `<directory>/frames/<prefix>_<digits>.h5`, sorted by step (numerically,
// so step 1000000000 sorts after 999999999). A missing frames folder gives an empty list.
std::vector<std::filesystem::path> listFrameFiles(const std::filesystem::path& directory, std::string_view prefix);

// Removes `<prefix>_*.h5.tmp` left in `<directory>/frames/` by a killed writer.
void removeStaleFrameTemporaries(const std::filesystem::path& directory, std::string_view prefix);

// fsyncs `temporary`, renames it over `destination` and fsyncs the folder, so after a
// crash the destination holds either its old or its new content.
void publishFile(const std::filesystem::path& temporary, const std::filesystem::path& destination);

// Creates `<directory>/frames` and removes temporaries a killed writer left there.
void prepareFrameFolder(const std::filesystem::path& directory, std::string_view prefix);

// Writes `destination` through `write(temporary)` and publishes it; a failure removes the
// temporary and leaves frames already written untouched.
template <class WriteFn>
void writeFrameFile(const std::filesystem::path& destination, WriteFn&& write) {
  const std::filesystem::path temporary = destination.string() + ".tmp";
  try {
    write(temporary);
    publishFile(temporary, destination);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(temporary, ec);
    throw;
  }
}

}  // namespace grainbridge::core::io
