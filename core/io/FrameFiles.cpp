#include "core/io/FrameFiles.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "core/Error.hpp"
#include "core/Files.hpp"

namespace grainbridge::core::io {

namespace {
// Step number if `name` is exactly "<prefix>_<digits><suffix>", else -1.
std::int64_t stepFromName(const std::string& name, std::string_view prefix, std::string_view suffix) {
  const std::string head = std::string(prefix) + "_";
  if (name.size() <= head.size() + suffix.size() || name.compare(0, head.size(), head) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) {
    return -1;
  }
  const std::string digits = name.substr(head.size(), name.size() - head.size() - suffix.size());
  if (digits.size() > 18 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return -1;
  }
  return std::stoll(digits);
}
}  // namespace

std::string frameFileName(std::string_view prefix, std::int64_t step) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%09lld", static_cast<long long>(step));
  return std::string(prefix) + "_" + digits + ".h5";
}

std::vector<std::filesystem::path> listFrameFiles(const std::filesystem::path& directory, std::string_view prefix) {
  const std::filesystem::path frames = directory / "frames";
  std::error_code ec;
  if (!std::filesystem::is_directory(frames, ec)) return {};
  std::vector<std::pair<std::int64_t, std::filesystem::path>> found;
  for (const auto& entry : std::filesystem::directory_iterator(frames)) {
    const std::int64_t step = stepFromName(entry.path().filename().string(), prefix, ".h5");
    if (step >= 0 && entry.is_regular_file()) found.emplace_back(step, entry.path());
  }
  std::sort(found.begin(), found.end());
  std::vector<std::filesystem::path> paths;
  paths.reserve(found.size());
  for (auto& f : found) paths.push_back(std::move(f.second));
  return paths;
}

void removeStaleFrameTemporaries(const std::filesystem::path& directory, std::string_view prefix) {
  const std::filesystem::path frames = directory / "frames";
  std::error_code ec;
  if (!std::filesystem::is_directory(frames, ec)) return;
  std::vector<std::filesystem::path> stale;
  for (const auto& entry : std::filesystem::directory_iterator(frames)) {
    if (stepFromName(entry.path().filename().string(), prefix, ".h5.tmp") >= 0) stale.push_back(entry.path());
  }
  for (const auto& p : stale) std::filesystem::remove(p, ec);
}

void publishFile(const std::filesystem::path& temporary, const std::filesystem::path& destination) {
  // HDF5 closes without fsync; without this a power loss after the rename could publish a
  // frame whose data never reached the disk.
  const int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const std::string reason = std::strerror(errno);
    if (fd >= 0) ::close(fd);
    throw Error("cannot flush '" + temporary.string() + "' to disk: " + reason);
  }
  ::close(fd);
  if (::rename(temporary.c_str(), destination.c_str()) != 0) {
    throw Error("cannot rename '" + temporary.string() + "' to '" + destination.string() +
                "': " + std::strerror(errno));
  }
  syncDirectory(destination.parent_path());
}

void prepareFrameFolder(const std::filesystem::path& directory, std::string_view prefix) {
  std::error_code ec;
  std::filesystem::create_directories(directory / "frames", ec);
  if (ec) throw Error("cannot create output folder '" + (directory / "frames").string() + "': " + ec.message());
  removeStaleFrameTemporaries(directory, prefix);
}

}  // namespace grainbridge::core::io
