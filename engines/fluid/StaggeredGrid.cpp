#include "engines/fluid/StaggeredGrid.hpp"

#include <string>

#include "core/Error.hpp"

namespace grainbridge::fluid {

StaggeredGrid::StaggeredGrid(core::data::GridGeometry geometry) : geometry_(std::move(geometry)) {
  for (int a = 0; a < 3; ++a) {
    const char* axis = a == 0 ? "x" : a == 1 ? "y" : "z";
    if (geometry_.cells[static_cast<std::size_t>(a)] < 1) {
      throw Error(std::string("staggered grid: ") + axis + " needs at least one cell, got " +
                  std::to_string(geometry_.cells[static_cast<std::size_t>(a)]));
    }
    if (!(geometry_.spacing[a] > 0.0)) {
      throw Error(std::string("staggered grid: the ") + axis + " spacing must be positive, got " +
                  std::to_string(geometry_.spacing[a]));
    }
  }
  for (int a = 0; a < 3; ++a) {
    padded_[static_cast<std::size_t>(a)] = static_cast<std::size_t>(cells(a) + 2 * ghosts(a));
  }
  stride_ = {1, padded_[0], padded_[0] * padded_[1]};
}

Vec3 StaggeredGrid::cellCentre(int i, int j, int k) const {
  const auto& g = geometry_;
  return g.origin + Vec3((i + 0.5) * g.spacing.x(), (j + 0.5) * g.spacing.y(), (k + 0.5) * g.spacing.z());
}

Vec3 StaggeredGrid::faceCentre(int axis, int i, int j, int k) const {
  Vec3 c = cellCentre(i, j, k);
  c[axis] += 0.5 * spacing(axis);
  return c;
}

double StaggeredGrid::cellVolume() const { return geometry_.spacing.prod(); }

double StaggeredGrid::faceArea(int axis) const { return cellVolume() / spacing(axis); }

}  // namespace grainbridge::fluid
