#pragma once
// SHA-256 (OpenSSL's EVP) of files and strings: artifact integrity in the stage cache and the
// content hash behind stage keys.
#include <filesystem>
#include <string>
#include <string_view>

namespace grainbridge::core {
std::string sha256Hex(std::string_view data);
// Streams the file; throws Error naming the path if it cannot be read.
std::string sha256File(const std::filesystem::path& path);
}  // namespace grainbridge::core
