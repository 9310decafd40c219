#pragma once
// Provenance every frame file carries as root attributes (DESIGN.md "Data contracts"):
// which stage instance wrote it (stage_key), with which code (code_version = git SHA,
// code_dirty), in which layout (format_version), and the frame's time, step and units.
// Provenance never enters a stage key; it lets the database trace a closure value back to
// the code that produced it.
#include <cstdint>
#include <filesystem>
#include <string>

namespace grainbridge::core::io {

class H5OutputFile;
class H5InputFile;

// Layout versions of the two file kinds. Bump on any incompatible layout change; readers
// refuse versions they do not know rather than misread them.
inline constexpr int kParticleFormatVersion = 1;
inline constexpr int kFieldFormatVersion = 1;

// What the writer is told about the stage instance it writes for.
struct ArtifactStamp {
  std::string stageKey;
};

// What a reader finds in a file.
struct FileStamp {
  std::string stageKey;
  std::string codeVersion;  // git SHA of the build that wrote the file
  bool codeDirty = false;   // the build had uncommitted changes
  int formatVersion = 0;
};

// Writes stage_key, code_version, code_dirty (from core::codeVersion()), format_version,
// time, step and units on the file root.
void writeFrameAttributes(H5OutputFile& file, const ArtifactStamp& stamp, int formatVersion, double time,
                          std::int64_t step, const std::string& units);

// Reads the provenance attributes of the file root; throws grainbridge::Error naming the
// file and the missing attribute.
FileStamp readStamp(const H5InputFile& file);
FileStamp readStamp(const std::filesystem::path& path);

// Throws unless 1 <= format_version <= newestSupported (naming file and attribute).
int checkFormatVersion(const H5InputFile& file, int newestSupported);

}  // namespace grainbridge::core::io
