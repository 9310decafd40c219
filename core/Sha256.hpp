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
// sha256File, once per file version in this process: an input file named by every instance of a
// sweep (a 4.5 MB LAMMPS data file) was hashed at each resolve of the config. A version is the
// canonical path with its size and modification time; a rewritten file is hashed again.
std::string sha256FileOncePerVersion(const std::filesystem::path& path);
}  // namespace grainbridge::core
