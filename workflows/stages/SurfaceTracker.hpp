#pragma once
// The `extract` stage's surface_particles option: for chosen particles (the Brazil nut), the
// height against the local free surface of the bed in every averaged frame
// (extract/structure/LocalFreeSurface.hpp), written as surface.csv, and when each particle
// reached the top and stayed there (VALIDATION.md: "at the top" means the large particle's top
// within 1 d0 of the local free surface).
//
// Only frames of a packed bed are judged: in a vibrated column the bed spends part of each cycle
// in flight (coordination below 1, Fig. 6.10), where no surface exists to be near. A frame is
// judged when its mean coordination number is at least min_coordination.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::workflows::stages {

struct SurfaceTrackerOptions {
  std::vector<std::int64_t> ids;
  Vec3 up = Vec3::UnitZ();
  double tolerance = 1.0;  // in diameters of the smallest grain of the frame
  double minCoordination = 2.0;
};

class SurfaceTracker {
 public:
  explicit SurfaceTracker(SurfaceTrackerOptions options);

  // `coordination` is the frame's mean coordination number. Throws grainbridge::Error naming
  // the id when the frame has no such particle.
  void add(const core::data::ParticleFrame& frame, double coordination);

  [[nodiscard]] std::string csv() const;
  // Flat keys surface_id<N>_*, per id: first_at_top_time, settled_at_top_time (the earliest
  // judged frame after which every judged frame is at the top; null if the last judged frame is
  // not), last_gap_diameters (at the last judged frame) and judged_frames.
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
  SurfaceTrackerOptions options_;
  std::vector<Row> rows_;
};

}  // namespace grainbridge::workflows::stages
