#pragma once
// The skeleton every frame writer shares (particle frames, field frames, and the multi-fluid
// engine's fields through FieldFrameWriter): one HDF5 file per frame in <directory>/frames,
// published atomically (FrameFiles.hpp), a temporal XDMF collection <prefix>.xmf rewritten after
// every frame so ParaView always opens what is on disk, and, on a directory that already holds
// frames (a restarted run), those frames rescanned into the collection and stray temporaries of
// a killed writer removed. A writer supplies only what differs: how to write one file, how to
// summarise one, and the XDMF grid of one time step.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>
#include <string>

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/io/FrameFiles.hpp"

namespace grainbridge::core::io {

// Summary: what the collection needs of one frame, with members `file` and `step`.
template <class Summary>
class FrameSeries {
 public:
  using ReadSummary = std::function<Summary(const std::filesystem::path&)>;
  // The <Grid> of one time step (indented for the collection); file names relative to the .xmf.
  using StepGrid = std::function<std::string(std::int64_t step, const Summary&)>;

  FrameSeries(std::filesystem::path directory, std::string prefix, const ReadSummary& readSummary, StepGrid stepGrid)
      : directory_(std::move(directory)), prefix_(std::move(prefix)), stepGrid_(std::move(stepGrid)) {
    prepareFrameFolder(directory_, prefix_);
    for (const auto& path : listFrameFiles(directory_, prefix_)) {
      try {
        Summary s = readSummary(path);
        frames_[s.step] = std::move(s);
      } catch (const Error& e) {
        throw e.withContext("while rescanning the frames of a restarted run");
      }
    }
    // A crash between publishing a frame and rewriting the sidecar leaves it one frame behind;
    // rewriting it here brings it back in line.
    if (!frames_.empty()) rewriteXdmf();
  }

  // Writes the frame of `step` through `writeFile(temporary)` (replacing a frame of the same
  // step), records `summary` for it and rewrites the collection. Frames already written are
  // untouched when writing fails.
  template <class WriteFn>
  std::filesystem::path write(std::int64_t step, WriteFn&& writeFile, Summary summary) {
    if (step < 0) throw Error(prefix_ + " frame step " + std::to_string(step) + " is negative");
    const std::filesystem::path path = directory_ / "frames" / frameFileName(prefix_, step);
    writeFrameFile(path, std::forward<WriteFn>(writeFile));
    summary.file = path;
    summary.step = step;
    frames_[step] = std::move(summary);
    rewriteXdmf();
    return path;
  }

  [[nodiscard]] const std::filesystem::path& directory() const { return directory_; }
  [[nodiscard]] std::filesystem::path xdmfPath() const { return directory_ / (prefix_ + ".xmf"); }
  [[nodiscard]] std::size_t frameCount() const { return frames_.size(); }

 private:
  // XDMF 2, for ParaView's "XDMF Reader" (why not the Xdmf3 readers: see
  // tests/integration/paraview_check.py): one temporal collection of the steps' grids.
  void rewriteXdmf() const {
    std::ostringstream x;
    x << "<?xml version=\"1.0\" ?>\n"
         "<Xdmf Version=\"2.0\">\n"
         " <Domain>\n"
         "  <Grid Name=\""
      << prefix_ << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& [step, s] : frames_) x << stepGrid_(step, s);
    x << "  </Grid>\n"
         " </Domain>\n"
         "</Xdmf>\n";
    writeFileAtomically(xdmfPath(), x.str());
  }

  std::filesystem::path directory_;
  std::string prefix_;
  StepGrid stepGrid_;
  std::map<std::int64_t, Summary> frames_;  // by step: the collection's order
};

}  // namespace grainbridge::core::io
