#include "core/io/CheckpointFile.hpp"

#include <cstdint>

#include "core/Error.hpp"
#include "core/io/FrameFiles.hpp"

namespace grainbridge::core::io {

void writeCheckpointFile(const std::filesystem::path& path, const CheckpointHeader& header,
                         const std::function<void(H5OutputFile&)>& writeContent) {
  // writeFrameFile: the temporary beside `path`, removed on failure; fsync, rename, folder sync.
  writeFrameFile(path, [&](const std::filesystem::path& temporary) {
    H5OutputFile f(temporary);
    f.writeAttribute("/", "format_version", static_cast<std::int32_t>(header.formatVersion));
    f.writeAttribute("/", "fingerprint", header.fingerprint);
    writeContent(f);
    f.close();
  });
}

H5InputFile openCheckpointFile(const std::filesystem::path& path, const CheckpointHeader& expected) {
  H5InputFile f(path);
  const auto version = f.readIntAttribute("/", "format_version");
  if (version != expected.formatVersion) {
    throw Error("checkpoint '" + path.string() + "' has format_version " + std::to_string(version) +
                ", this build reads " + std::to_string(expected.formatVersion));
  }
  if (f.readStringAttribute("/", "fingerprint") != expected.fingerprint) {
    throw Error("checkpoint '" + path.string() + "' belongs to another configuration");
  }
  return f;
}

}  // namespace grainbridge::core::io
