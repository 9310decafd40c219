#pragma once
// The tiny Lees-Edwards shear run several workflow tests start from: 40 grains of 1 mm in a
// 6 mm periodic box at gammadot = 100 1/s for 0.02 s (k* = 1e5, dt ~ t_c/50). Enough for
// closure points and field frames to exist, not physics. Tests change the parameters they need.
#include <nlohmann/json.hpp>

namespace grainbridge::testing {

inline nlohmann::json tinyShearDemParams() {
  return {{"box_lo", {0, 0, 0}},
          {"box_hi", {"6 mm", "6 mm", "6 mm"}},
          {"periodic", "xyz"},
          {"gravity", {0, 0, 0}},
          {"shear_rate", "100 1/s"},
          {"dt", "1e-6 s"},
          {"duration", "0.02 s"},
          {"frames", 4},
          {"series_points", 2},
          {"progress", false},
          {"species", {{{"name", "grain"}, {"diameter", "1 mm"}, {"density", "2500 kg/m3"}, {"count", 40}}}},
          {"contact", {{"kn", "2500 N/m"}, {"restitution", 0.9}, {"mu", 0.0}}}};
}

}  // namespace grainbridge::testing
