#pragma once
// Coarse-grained fields of every averaged frame (Eq. 2.3 on a grid over the frame's domain,
// extract/coarse/CoarseGrain) written as field frames for ParaView (fields.xmf), and their time
// average with block-averaging errors (core/averaging/FieldTimeAverage) as a one-frame
// collection mean/fields.xmf. The solids phases are the frames' species, named as their
// materials name them.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/averaging/FieldTimeAverage.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "extract/coarse/CoarseGrain.hpp"
#include "extract/coarse/CoarseGrainingKernel.hpp"
#include "extract/observe/FrameObserver.hpp"

namespace grainbridge::extract::observe {

struct FieldOptions {
  std::array<int, 3> cells{1, 1, 1};
  coarse::CoarseGrainingKernel kernel;
  std::vector<std::string> speciesNames;  // index = species; "species<k>" beyond the list
  std::filesystem::path outputDir;        // the instance folder: frames/, fields.xmf, mean/
  core::io::ArtifactStamp stamp;
};

class FieldObserver final : public FrameObserver {
 public:
  explicit FieldObserver(FieldOptions options);
  void observe(ObservedFrame& frame) override;
  void finish(OutputSink& out, ExtractResult& result) override;

 private:
  FieldOptions options_;
  core::io::FieldFrameWriter writer_;
  coarse::CoarseGrainer coarseGrainer_;  // keeps its cell arrays from frame to frame
  core::averaging::FieldTimeAverage average_;
};

// The coarse-grained fields of one frame as a field frame: the solids phases (one per species)
// in the continuum slots, everything else DEM adds (stress tensors, pressure, coordination,
// forces) as named extra fields.
core::data::FieldFrame toFieldFrame(const core::data::ParticleFrame& frame, const coarse::CoarseFields& fields,
                                    const std::vector<std::string>& speciesNames);

}  // namespace grainbridge::extract::observe
