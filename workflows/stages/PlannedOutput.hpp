#pragma once
// What a stage instance will produce, known from its resolved params before it runs. A
// downstream stage checks its requests against it at config load (an averaging window against
// the run's last frame, particle ids against the particles inserted), so a request that cannot
// be met is refused before any upstream work rather than after an hour of DEM. Each field is
// set only when the params alone determine it.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace grainbridge::workflows::stages {

// The grains a product is of, where one kind of mobile grain made it: what makes an inertial
// number, so that a continuum stage can refuse a rheology measured on other grains.
struct Grains {
  double diameter = 0.0;  // m
  double density = 0.0;   // kg/m^3
};

struct PlannedOutput {
  bool particleFrames = false;                 // writes frames/particles_*.h5 (kind particle_frame)
  // Writes field frames (frames/fields_*.h5, kind field_frame) stamped with their materials:
  // gravity and each solids phase's name, diameter and density (core/data/FieldFrame).
  bool fieldFrames = false;
  bool meanFieldFrames = false;                // writes time-averaged fields (kind mean_field_frame)
  bool closurePoint = false;                   // records a closure point (closure_points; its summary: the point)
  std::optional<double> lastFrameTime;         // s; particle frames span [0, lastFrameTime]
  std::optional<double> leesEdwardsShearRate;  // 1/s; 0 when the run is not sheared
  std::optional<std::int64_t> particleCount;   // particles with ids 0..count-1 (none read from a file)
  // Summary values it will record that downstream stages read, per phase where there are phases
  // (mean_height_<phase>). Continuum beds: pressure_drop (the first tap's drop; the summary's
  // pressure_drop_tap names that tap, whose series column is dp_<tap>), mean_height (Eq. 5.22
  // over all solids), mean_height_<phase>, solids_volume_change_<phase>, closure,
  // superficial_gas_velocity (m/s, what the inlets impose: fluid::superficialGasVelocity).
  // Particle runs (dem): seed (of a random insertion), side_wall_friction (of a cylinder wall).
  std::vector<std::string> summaryKeys;
  std::vector<std::string> seriesColumns;      // columns of series.csv that downstream stages read
  std::optional<std::string> closureTables;    // the name of the closure tables it makes (tabulate)
  // The one kind of mobile grain of a particle run. Stages that do not say (extract, tabulate)
  // are given the grains all their upstream instances agree on by the config loader, so the
  // grains reach the stages downstream of the DEM through every stage in between.
  std::optional<Grains> grains;
};

// One upstream instance as the config loader hands it to a downstream stage's check.
struct UpstreamPlan {
  std::string stage;                                     // its stage name, for messages
  nlohmann::json sweepPoint = nlohmann::json::object();  // {} unless the upstream is swept
  nlohmann::json sweepWritten = nlohmann::json::object();  // the same point as the config wrote it
  PlannedOutput output;  // empty for a type that promises nothing

  [[nodiscard]] bool records(const std::string& summaryKey) const;
  [[nodiscard]] bool writesSeriesColumn(const std::string& column) const;
};

inline bool UpstreamPlan::records(const std::string& summaryKey) const {
  const auto& keys = output.summaryKeys;
  return std::find(keys.begin(), keys.end(), summaryKey) != keys.end();
}

inline bool UpstreamPlan::writesSeriesColumn(const std::string& column) const {
  const auto& columns = output.seriesColumns;
  return std::find(columns.begin(), columns.end(), column) != columns.end();
}

// The first upstream in `upstream` that records no closure point, or nullptr: tabulate and
// compare take only stages that do (extract).
inline const UpstreamPlan* withoutClosurePoint(const std::vector<UpstreamPlan>& upstream) {
  for (const auto& up : upstream) {
    if (!up.output.closurePoint) return &up;
  }
  return nullptr;
}

}  // namespace grainbridge::workflows::stages
