#pragma once
// The file every engine checkpoint is: one HDF5 file holding the state a run continues from bit
// for bit, with the same header on "/" whichever engine wrote it -- `format_version` (the layout
// of the content, bumped by its engine when that changes) and `fingerprint` (the configuration
// that wrote it, the stage key) -- so a checkpoint of another layout or another run is refused
// with one message. It is written into "<path>.tmp", closed, flushed to disk and renamed over
// <path>, and the folder is synced (core/io/FrameFiles publishFile), so a kill at any moment
// leaves the previous checkpoint intact. The content is the engine's: it writes its state into
// a group of the open file (the root for one engine; a coupled engine such as TF-DEM puts the
// particles' state and the fluid's each in its own group of one file).
#include <filesystem>
#include <functional>
#include <string>

#include "core/io/H5InputFile.hpp"
#include "core/io/H5OutputFile.hpp"

namespace grainbridge::core::io {

struct CheckpointHeader {
  int formatVersion = 0;
  std::string fingerprint;
};

// Writes the header, then the content through `writeContent`, and publishes the file. A failure
// anywhere removes the temporary and leaves an existing checkpoint at `path` untouched.
void writeCheckpointFile(const std::filesystem::path& path, const CheckpointHeader& header,
                         const std::function<void(H5OutputFile&)>& writeContent);

// Opens a checkpoint for reading its content. Throws grainbridge::Error naming the file if it is
// unreadable, of another format version ("checkpoint '<path>' has format_version N, this build
// reads M") or of another configuration ("checkpoint '<path>' belongs to another configuration").
[[nodiscard]] H5InputFile openCheckpointFile(const std::filesystem::path& path, const CheckpointHeader& expected);

}  // namespace grainbridge::core::io
