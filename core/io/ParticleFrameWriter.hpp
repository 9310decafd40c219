#pragma once
// Writes particle frames as one closed HDF5 file per frame plus the ParaView sidecar
// particles.xmf (DESIGN.md "Data contracts"):
//
//   <directory>/frames/particles_<step, 9 digits>.h5
//     @time @step @format_version @units @stage_key @code_version @code_dirty
//     /domain  @lo @hi (3) @periodic (3 x 0/1) @lees_edwards_offset @lees_edwards_shear_rate
//              wall_kind [W] (0 plane, 1 cylinder; @codes explains) wall_origin [W,3]
//              wall_direction [W,3] wall_radius [W] wall_velocity [W,3]
//     /id [N] /species [N] /radius [N] /mass [N] /position [N,3] /velocity [N,3]
//     /angular_velocity [N,3] (/external_force [N,3] only when the frame has one)
//     /contacts/ i j [M], branch contact_point force_normal force_tangential
//                force_normal_elastic force_normal_dissipative force_tangential_elastic
//                force_tangential_dissipative [M,3]; derived for viewers: segments [2M,3]
//                (r_i, r_i - branch per contact) and segment_connectivity [M,2]
//     /wall_contacts/ particle [Mw] wall [Mw] point force_normal force_tangential [Mw,3]
//   <directory>/particles.xmf  temporal collection over every frame in frames/
//
// Equal frames give byte-identical files (no timestamps, pinned format), so the artifact
// sha256 in the database only changes when the content does.
#include <cstdint>
#include <filesystem>
#include <map>

#include "core/data/ParticleFrame.hpp"
#include "core/io/FrameMetadata.hpp"
#include "core/io/FrameSeries.hpp"
#include "core/io/ParticleFrameReader.hpp"

namespace grainbridge::core::io {

class ParticleFrameWriter {
 public:
  // Creates `directory`/frames if needed. On a directory that already holds frames (a
  // restarted run) the existing frames are rescanned into the XDMF collection and stray
  // temporaries from a killed writer are removed. deflateLevel 0 (default) stores plain
  // contiguous datasets; 1..9 deflates them.
  ParticleFrameWriter(std::filesystem::path directory, ArtifactStamp stamp, int deflateLevel = 0);

  // Validates and writes one frame (replacing a frame of the same step), then rewrites
  // particles.xmf. Returns the frame's path. Throws grainbridge::Error on invalid frames
  // (contact ids not in the frame, inconsistent arrays) or I/O failure; frames already
  // written are untouched either way.
  std::filesystem::path write(const data::ParticleFrame& frame);

  [[nodiscard]] const std::filesystem::path& directory() const { return series_.directory(); }
  [[nodiscard]] std::filesystem::path xdmfPath() const { return series_.xdmfPath(); }
  [[nodiscard]] std::size_t frameCount() const { return series_.frameCount(); }

 private:
  void writeFile(const std::filesystem::path& path, const data::ParticleFrame& frame) const;

  ArtifactStamp stamp_;
  int deflateLevel_;
  FrameSeries<ParticleFrameSummary> series_;  // folder, atomic files, particles.xmf, rescan
};

}  // namespace grainbridge::core::io
