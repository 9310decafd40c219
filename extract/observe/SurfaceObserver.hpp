#pragma once
// For chosen particles (the Brazil nut), the height against the local free surface of the bed
// in every averaged frame (extract/structure/LocalFreeSurface.hpp), written as surface.csv, and
// when each particle reached the top and stayed there (VALIDATION.md: "at the top" means the
// large particle's top within 1 d0 of the local free surface).
//
// Only frames of a packed bed are judged: in a vibrated column the bed spends part of each cycle
// in flight (coordination below 1, Fig. 6.10), where no surface exists to be near. A frame is
// judged when its mean coordination number is at least minCoordination.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "extract/observe/FrameObserver.hpp"

namespace grainbridge::extract::observe {

struct SurfaceOptions {
  std::vector<std::int64_t> ids;
  Vec3 up = Vec3::UnitZ();  // against gravity (core/data/Materials::up)
  double tolerance = 1.0;   // in diameters of the smallest grain of the frame
  double minCoordination = 2.0;
};

class SurfaceObserver final : public FrameObserver {
 public:
  explicit SurfaceObserver(SurfaceOptions options) : options_(std::move(options)) {}
  // Throws grainbridge::Error naming the id when the frame has no such particle.
  void observe(ObservedFrame& frame) override;
  // Writes surface.csv; adds to the summary, per id: surface_id<N>_first_at_top_time,
  // _settled_at_top_time (the earliest judged frame after which every judged frame is at the
  // top; null if the last judged frame is not), _last_gap_diameters and _judged_frames.
  void finish(OutputSink& out, ExtractResult& result) override;
  [[nodiscard]] std::string parameter() const override { return "surface_particles"; }

  [[nodiscard]] std::string csv() const;
  [[nodiscard]] nlohmann::json summary() const;

 private:
  struct Row {
    double time;
    std::int64_t step, id;
    double top, surface, gap, gapDiameters;
    std::size_t covering;
    double coordination;
    bool judged, atTop;
  };
  SurfaceOptions options_;
  std::vector<Row> rows_;
};

}  // namespace grainbridge::extract::observe
