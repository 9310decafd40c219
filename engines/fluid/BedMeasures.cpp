#include "engines/fluid/BedMeasures.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::fluid {

VerticalAxis verticalAxis(const Vec3& gravity) {
  VerticalAxis v;
  Eigen::Index axis = 1;
  gravity.cwiseAbs().maxCoeff(&axis);
  v.axis = static_cast<int>(axis);
  v.up = gravity[axis] > 0.0 ? -1.0 : 1.0;
  return v;
}

namespace {

// Height of cell row r along the vertical axis, from the low (up = +1) or high (up = -1) side.
double rowHeight(const StaggeredGrid& grid, VerticalAxis v, int row) {
  const int n = grid.cells(v.axis);
  const int fromBottom = v.up > 0.0 ? row : n - 1 - row;
  return (fromBottom + 0.5) * grid.spacing(v.axis);
}

// Mean P_g over the cells of one row.
double rowPressure(const FlowState& state, VerticalAxis v, int row) {
  const auto& grid = state.grid();
  double sum = 0.0;
  long count = 0;
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::array<int, 3> at{i, j, k};
        if (at[static_cast<std::size_t>(v.axis)] != row) continue;
        sum += state.pressure(i, j, k);
        ++count;
      }
    }
  }
  return sum / static_cast<double>(count);
}

}  // namespace

double pressureAtHeight(const FlowState& state, VerticalAxis v, double height) {
  const auto& grid = state.grid();
  const int n = grid.cells(v.axis);
  const double h = grid.spacing(v.axis);
  // Rows counted from the bottom: b = 0 is the lowest.
  auto row = [&](int b) { return v.up > 0.0 ? b : n - 1 - b; };
  if (n == 1) return rowPressure(state, v, 0);
  const double position = height / h - 0.5;  // in row centres from the bottom one
  const int below = std::clamp(static_cast<int>(std::floor(position)), 0, n - 2);
  const double w = position - below;  // < 0 below the first centre: extrapolation
  return (1.0 - w) * rowPressure(state, v, row(below)) + w * rowPressure(state, v, row(below + 1));
}

double bottomArea(const core::data::GridGeometry& geometry, VerticalAxis vertical) {
  double area = 1.0;
  for (int a = 0; a < 3; ++a) {
    if (a != vertical.axis) area *= geometry.cells[static_cast<std::size_t>(a)] * geometry.spacing[a];
  }
  return area;
}

double meanParticleHeight(const FlowState& state, VerticalAxis v, std::size_t m) {
  const auto& grid = state.grid();
  double weighted = 0.0, total = 0.0;
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::array<int, 3> at{i, j, k};
        const double eps = state.phases[m].fraction(i, j, k) * grid.cellVolume();
        weighted += eps * rowHeight(grid, v, at[static_cast<std::size_t>(v.axis)]);
        total += eps;
      }
    }
  }
  return total > 0.0 ? weighted / total : 0.0;
}

double solidsVolume(const FlowState& state, std::size_t m) {
  const auto& grid = state.grid();
  double total = 0.0;
  for (int k = 0; k < grid.cells(2); ++k)
    for (int j = 0; j < grid.cells(1); ++j)
      for (int i = 0; i < grid.cells(0); ++i) total += state.phases[m].fraction(i, j, k);
  return total * grid.cellVolume();
}

double meanGranularTemperature(const FlowState& state, std::size_t m) {
  const auto& grid = state.grid();
  double weighted = 0.0, volume = 0.0;
  for (int k = 0; k < grid.cells(2); ++k)
    for (int j = 0; j < grid.cells(1); ++j)
      for (int i = 0; i < grid.cells(0); ++i) {
        const double eps = std::max(state.phases[m].fraction(i, j, k), 0.0);
        weighted += eps * state.phases[m].granularTemperature(i, j, k);
        volume += eps;
      }
  return volume > 0.0 ? weighted / volume : 0.0;
}

double mixtureMeanHeight(const std::vector<double>& heights, const std::vector<double>& volumes) {
  double moment = 0.0, volume = 0.0;
  for (std::size_t m = 0; m < heights.size() && m < volumes.size(); ++m) {
    moment += volumes[m] * heights[m];
    volume += volumes[m];
  }
  return volume > 0.0 ? moment / volume : 0.0;
}

double segregationPercentage(double smallHeight, double largeHeight, double smallShare) {
  if (!(smallShare > 0.0 && smallShare < 1.0))
    throw Error("segregation percentage: the small particles' share " + std::to_string(smallShare) +
                " of the solids is not in (0, 1)");
  if (!(smallHeight > 0.0 && largeHeight > 0.0))
    throw Error("segregation percentage: mean heights " + std::to_string(smallHeight) + " m (small) and " +
                std::to_string(largeHeight) + " m (large) must be positive");
  const double ratio = smallHeight / largeHeight;                   // Eq. 5.24
  const double ratioMax = (2.0 - smallShare) / (1.0 - smallShare);  // Eq. 5.25
  return 100.0 * (ratio - 1.0) / (ratioMax - 1.0);                  // Eq. 5.23, in percent
}

}  // namespace grainbridge::fluid
