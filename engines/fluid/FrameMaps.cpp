#include "engines/fluid/FrameMaps.hpp"

#include <array>
#include <string>

#include "core/Error.hpp"
#include "engines/fluid/BedMeasures.hpp"

namespace grainbridge::fluid {

namespace {

// The frame's axes: vertical (against gravity), horizontal and depth, and the vertical's sense.
struct PlaneAxes {
  int vertical = 1, horizontal = 0, depth = 2;
  bool up = true;  // height grows with the vertical coordinate
};

PlaneAxes planeAxes(const core::data::FieldFrame& frame) {
  if (frame.materials.empty())
    throw Error("field frame at t = " + std::to_string(frame.time) + " s carries no materials (gravity)");
  const VerticalAxis v = verticalAxis(frame.materials.gravity);
  PlaneAxes a;
  a.vertical = v.axis;
  a.horizontal = v.axis == 0 ? 1 : 0;
  a.depth = 3 - a.vertical - a.horizontal;
  a.up = v.up > 0.0;
  return a;
}

// The sum over `phases` of the solids fraction at (column, row), averaged over the depth.
template <class Phases>
double depthMean(const core::data::FieldFrame& frame, const PlaneAxes& a, int column, int row, const Phases& phases) {
  const auto& g = frame.grid;
  const int layers = g.cells[static_cast<std::size_t>(a.depth)];
  double sum = 0.0;
  for (int l = 0; l < layers; ++l) {
    std::array<int, 3> ijk{};
    ijk[static_cast<std::size_t>(a.horizontal)] = column;
    ijk[static_cast<std::size_t>(a.vertical)] = row;
    ijk[static_cast<std::size_t>(a.depth)] = l;
    const std::size_t cell = g.index(ijk[0], ijk[1], ijk[2]);
    for (const std::size_t m : phases) sum += frame.solids[m].ep_s[cell];
  }
  return sum / layers;
}

}  // namespace

PlaneMap solidsFractionMap(const core::data::FieldFrame& frame) {
  const PlaneAxes a = planeAxes(frame);
  const auto& g = frame.grid;
  PlaneMap map;
  map.columns = g.cells[static_cast<std::size_t>(a.horizontal)];
  map.rows = g.cells[static_cast<std::size_t>(a.vertical)];
  map.x0 = g.origin[a.horizontal];
  map.y0 = g.origin[a.vertical];
  map.dx = g.spacing[a.horizontal];
  map.dy = g.spacing[a.vertical];
  std::vector<std::size_t> all;
  for (std::size_t m = 0; m < frame.solids.size(); ++m) all.push_back(m);
  map.values.reserve(static_cast<std::size_t>(map.columns) * map.rows);
  for (int r = 0; r < map.rows; ++r) {
    for (int c = 0; c < map.columns; ++c) map.values.push_back(depthMean(frame, a, c, r, all));
  }
  return map;
}

HeightProfile solidsFractionProfile(const core::data::FieldFrame& frame, std::size_t m) {
  const PlaneAxes a = planeAxes(frame);
  if (m >= frame.solids.size())
    throw Error("field frame has " + std::to_string(frame.solids.size()) + " solids phases, not a phase " +
                std::to_string(m));
  const auto& g = frame.grid;
  const int rows = g.cells[static_cast<std::size_t>(a.vertical)];
  const int columns = g.cells[static_cast<std::size_t>(a.horizontal)];
  const double h = g.spacing[a.vertical];
  const std::array<std::size_t, 1> phase{m};
  HeightProfile profile;
  for (int k = 0; k < rows; ++k) {
    const int row = a.up ? k : rows - 1 - k;  // from the bottom up
    double sum = 0.0;
    for (int c = 0; c < columns; ++c) sum += depthMean(frame, a, c, row, phase);
    profile.heights.push_back((k + 0.5) * h);
    profile.fraction.push_back(sum / columns);
  }
  return profile;
}

}  // namespace grainbridge::fluid
