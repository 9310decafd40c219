#pragma once
// Writes continuum field frames as one closed HDF5 file per frame plus the ParaView
// sidecar fields.xmf (DESIGN.md "Data contracts"):
//
//   <directory>/frames/fields_<step, 9 digits>.h5
//     @time @step @format_version @units @stage_key @code_version @code_dirty
//     /grid   @origin (x y z) @spacing (dx dy dz) @cells (nx ny nz)
//     /ep_g [nz,ny,nx]  /p_g [nz,ny,nx]  /u_g [nz,ny,nx,3]
//     /solids/<name>  @index (phase order)  ep_s [nz,ny,nx] u_s [nz,ny,nx,3] theta [nz,ny,nx]
//     /materials  gravity and each solids phase's name, diameter and density (core/io/MaterialsIo),
//                 when the frame has them
//   <directory>/fields.xmf  temporal collection of 3DCoRectMesh grids, Center="Cell"
//
// Cell-centred values only; equal frames give byte-identical files.
#include <cstdint>
#include <filesystem>
#include <map>

#include "core/data/FieldFrame.hpp"
#include "core/io/FieldFrameReader.hpp"
#include "core/io/FrameMetadata.hpp"
#include "core/io/FrameSeries.hpp"

namespace grainbridge::core::io {

class FieldFrameWriter {
 public:
  // Same contract as ParticleFrameWriter: creates `directory`/frames, and on a restarted
  // run rescans existing frames into the collection.
  FieldFrameWriter(std::filesystem::path directory, ArtifactStamp stamp, int deflateLevel = 0);

  // Validates and writes one frame (replacing a frame of the same step), then rewrites
  // fields.xmf. Returns the frame's path.
  std::filesystem::path write(const data::FieldFrame& frame);

  [[nodiscard]] const std::filesystem::path& directory() const { return series_.directory(); }
  [[nodiscard]] std::filesystem::path xdmfPath() const { return series_.xdmfPath(); }
  [[nodiscard]] std::size_t frameCount() const { return series_.frameCount(); }

 private:
  void writeFile(const std::filesystem::path& path, const data::FieldFrame& frame) const;

  ArtifactStamp stamp_;
  int deflateLevel_;
  FrameSeries<FieldFrameSummary> series_;  // folder, atomic files, fields.xmf, rescan
};

}  // namespace grainbridge::core::io
