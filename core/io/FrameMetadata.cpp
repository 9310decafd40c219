#include "core/io/FrameMetadata.hpp"

#include "core/Version.hpp"
#include "core/io/H5InputFile.hpp"
#include "core/io/H5OutputFile.hpp"

namespace grainbridge::core::io {

void writeFrameAttributes(H5OutputFile& file, const ArtifactStamp& stamp, int formatVersion, double time,
                          std::int64_t step, const std::string& units) {
  const CodeVersion& version = codeVersion();
  file.writeAttribute("/", "time", time);
  file.writeAttribute("/", "step", step);
  file.writeAttribute("/", "format_version", std::int32_t{formatVersion});
  file.writeAttribute("/", "units", units);
  file.writeAttribute("/", "stage_key", stamp.stageKey);
  file.writeAttribute("/", "code_version", version.gitSha);
  file.writeAttribute("/", "code_dirty", std::int32_t{version.dirty ? 1 : 0});
}

FileStamp readStamp(const H5InputFile& file) {
  FileStamp stamp;
  stamp.stageKey = file.readStringAttribute("/", "stage_key");
  stamp.codeVersion = file.readStringAttribute("/", "code_version");
  stamp.codeDirty = file.readIntAttribute("/", "code_dirty") != 0;
  stamp.formatVersion = static_cast<int>(file.readIntAttribute("/", "format_version"));
  return stamp;
}

FileStamp readStamp(const std::filesystem::path& path) { return readStamp(H5InputFile(path)); }

int checkFormatVersion(const H5InputFile& file, int newestSupported) {
  const std::int64_t version = file.readIntAttribute("/", "format_version");
  if (version < 1 || version > newestSupported) {
    throw file.error("attribute", "/@format_version",
                     "unsupported format version " + std::to_string(version) + " (this build reads 1 to " +
                         std::to_string(newestSupported) + "; a newer grainbridge wrote it?)");
  }
  return static_cast<int>(version);
}

}  // namespace grainbridge::core::io
