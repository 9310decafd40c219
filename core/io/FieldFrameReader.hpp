#pragma once
// Reads field frames written by FieldFrameWriter (layout in FieldFrameWriter.hpp). Errors
// are grainbridge::Error naming the file and the dataset or attribute.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/data/FieldFrame.hpp"
#include "core/io/FrameMetadata.hpp"  // readStamp(path) works on field frames too

namespace grainbridge::core::io {

// What the XDMF sidecar needs to know about a frame, read without loading the arrays.
struct FieldFrameSummary {
  std::filesystem::path file;
  std::int64_t step = 0;
  double time = 0.0;
  data::GridGeometry grid;
  std::vector<std::string> solidsPhases;            // in the frame's phase order
  std::vector<std::pair<std::string, int>> extras;  // name and components, in the frame's order
};

data::FieldFrame readFieldFrame(const std::filesystem::path& path);
FieldFrameSummary readFieldFrameSummary(const std::filesystem::path& path);

// `<directory>/frames/fields_*.h5`, sorted by step; empty if there are none.
std::vector<std::filesystem::path> listFieldFrames(const std::filesystem::path& directory);

}  // namespace grainbridge::core::io
