#pragma once
// The state the multiphase solver advances: the gas pressure P_g and, per phase m (0 the gas,
// 1..M the solids phases of a multi-fluid model or the particle phase of TF-DEM), its volume
// fraction eps_m and velocity v_m, the velocity's components on the staggered faces
// (StaggeredGrid.hpp), and for a solids phase of a kinetic-theory model its granular temperature
// theta (Eq. 5.6), a cell field the model's own transport equation advances (FlowModel::
// solveTransport); zero where nothing solves for it. The fractions sum to one in every cell (eps_g = 1 - sum eps_s): the solver
// keeps them so and never clips one (clipping would break mass conservation).
#include <array>
#include <cstddef>
#include <vector>

#include "engines/fluid/Fields.hpp"

namespace grainbridge::fluid {

struct PhaseFields {
  explicit PhaseFields(const StaggeredGrid& grid)
      : fraction(grid),
        velocity{FaceField(grid, 0), FaceField(grid, 1), FaceField(grid, 2)},
        granularTemperature(grid) {}
  CellField fraction;                 // eps_m [-]
  std::array<FaceField, 3> velocity;  // v_m on the faces of each axis [m/s]
  CellField granularTemperature;      // theta_m [m^2/s^2]; ghosts zero-gradient (Boundaries::apply)
};

struct FlowState {
  FlowState(const StaggeredGrid& grid, std::size_t phaseCount) : pressure(grid) {
    phases.reserve(phaseCount);
    for (std::size_t m = 0; m < phaseCount; ++m) phases.emplace_back(grid);
  }
  double time = 0.0;                // [s]
  CellField pressure;               // P_g [Pa]
  std::vector<PhaseFields> phases;  // [0] the gas

  [[nodiscard]] const StaggeredGrid& grid() const { return pressure.grid(); }
};

}  // namespace grainbridge::fluid
