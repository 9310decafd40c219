#pragma once
// What a stage instance will produce, known from its resolved params before it runs. A
// downstream stage checks its requests against it at config load (an averaging window against
// the run's last frame, particle ids against the particles inserted), so a request that cannot
// be met is refused before any upstream work rather than after an hour of DEM. Each field is
// set only when the params alone determine it.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace grainbridge::workflows::stages {

struct PlannedOutput {
  bool particleFrames = false;                 // writes frames/particles_*.h5
  std::optional<double> lastFrameTime;         // s; particle frames span [0, lastFrameTime]
  std::optional<double> leesEdwardsShearRate;  // 1/s; 0 when the run is not sheared
  std::optional<std::int64_t> particleCount;   // particles with ids 0..count-1 (none read from a file)
  std::vector<std::string> summaryKeys;        // summary values it will record that downstream checks read
  std::optional<std::string> closureTables;    // the name of the closure tables it makes (tabulate)
};

// One upstream instance as the config loader hands it to a downstream stage's check.
struct UpstreamPlan {
  std::string stage;                                     // its stage name, for messages
  nlohmann::json sweepPoint = nlohmann::json::object();  // {} unless the upstream is swept
  PlannedOutput output;
};

}  // namespace grainbridge::workflows::stages
