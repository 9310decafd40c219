#include "engines/fluid/FlowFrame.hpp"

#include "engines/fluid/FieldSampling.hpp"

namespace grainbridge::fluid {

core::data::FieldFrame flowFrame(const StaggeredGrid& grid, const FlowState& flow, std::int64_t step,
                                 const std::vector<std::string>& solids, const SolidsCellFill& fill) {
  core::data::FieldFrame f;
  f.time = flow.time;
  f.step = step;
  f.units = "SI";
  f.grid = grid.geometry();
  const std::size_t n = f.grid.cellCount();
  f.ep_g.resize(n);
  f.p_g.resize(n);
  f.u_g.resize(n);
  for (const auto& name : solids) {
    core::data::SolidsPhaseFields phase;
    phase.name = name;
    phase.ep_s.resize(n);
    phase.u_s.resize(n);
    phase.theta.resize(n);
    f.solids.push_back(std::move(phase));
  }
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k), out = f.grid.index(i, j, k);
        f.ep_g[out] = flow.phases[0].fraction[c];
        f.p_g[out] = flow.pressure[c];
        f.u_g[out] = cellVelocity(flow.phases[0], c);
        fill(c, out, f.solids);
      }
    }
  }
  return f;
}

}  // namespace grainbridge::fluid
