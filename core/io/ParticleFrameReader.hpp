#pragma once
// Reads particle frames written by ParticleFrameWriter (layout in ParticleFrameWriter.hpp).
// Extract and the tests read through here, never through HDF5 directly. Every failure is a
// grainbridge::Error naming the file and the dataset or attribute: a missing file, a
// non-HDF5 file, a missing dataset, a wrong shape or type, or an unknown format_version.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/data/ParticleFrame.hpp"
#include "core/io/FrameMetadata.hpp"  // readStamp(path) works on particle frames too

namespace grainbridge::core::io {

// What the XDMF sidecar needs to know about a frame, read without loading the arrays.
struct ParticleFrameSummary {
  std::filesystem::path file;
  std::int64_t step = 0;
  double time = 0.0;
  std::size_t particles = 0;
  std::size_t contacts = 0;
  bool hasExternalForce = false;
};

data::ParticleFrame readParticleFrame(const std::filesystem::path& path);
ParticleFrameSummary readParticleFrameSummary(const std::filesystem::path& path);

// `<directory>/frames/particles_*.h5`, sorted by step; empty if there are none.
std::vector<std::filesystem::path> listParticleFrames(const std::filesystem::path& directory);

}  // namespace grainbridge::core::io
