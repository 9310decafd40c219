#pragma once
// What reading any frame file shares (particle frames, field frames): the file opened, its
// format_version checked, the attributes every frame carries (time, step, units) read before the
// frame's own datasets, and its materials and its own validation after them, a validation error
// naming the file. Written once so that the two readers check and report alike.
#include <filesystem>
#include <utility>

#include "core/Error.hpp"
#include "core/io/FrameMetadata.hpp"
#include "core/io/H5InputFile.hpp"
#include "core/io/MaterialsIo.hpp"

namespace grainbridge::core::io {

// A Frame (data::ParticleFrame, data::FieldFrame) from `path`, a file of format_version at most
// `newestSupported`; readDatasets(file, frame) reads what is the frame type's own.
template <class Frame, class ReadDatasets>
Frame readFrameFile(const std::filesystem::path& path, int newestSupported, ReadDatasets&& readDatasets) {
  const H5InputFile f(path);
  checkFormatVersion(f, newestSupported);
  Frame frame;
  frame.time = f.readDoubleAttribute("/", "time");
  frame.step = f.readIntAttribute("/", "step");
  frame.units = f.readStringAttribute("/", "units");
  std::forward<ReadDatasets>(readDatasets)(f, frame);
  frame.materials = readMaterials(f);
  try {
    frame.validate();
  } catch (const Error& e) {
    throw e.withContext("file '" + path.string() + "'");
  }
  return frame;
}

// A Summary (ParticleFrameSummary, FieldFrameSummary) of the frame file `path`: its file, step and
// time; readRest(file, summary) reads what is the summary type's own.
template <class Summary, class ReadRest>
Summary readFrameFileSummary(const std::filesystem::path& path, int newestSupported, ReadRest&& readRest) {
  const H5InputFile f(path);
  checkFormatVersion(f, newestSupported);
  Summary s;
  s.file = path;
  s.step = f.readIntAttribute("/", "step");
  s.time = f.readDoubleAttribute("/", "time");
  std::forward<ReadRest>(readRest)(f, s);
  return s;
}

}  // namespace grainbridge::core::io
