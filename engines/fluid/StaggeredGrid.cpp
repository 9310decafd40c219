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
  coordinates_.resize(paddedCount());
  interior_.resize(paddedCount());
  for (std::size_t c = 0; c < paddedCount(); ++c) {
    const int i = static_cast<int>(c % padded_[0]) - ghosts(0);
    const int j = static_cast<int>((c / padded_[0]) % padded_[1]) - ghosts(1);
    const int k = static_cast<int>(c / (padded_[0] * padded_[1])) - ghosts(2);
    coordinates_[c] = {i, j, k};
    interior_[c] = interior(i, j, k) ? 1 : 0;
  }
  cellVolume_ = geometry_.spacing.prod();
  for (int a = 0; a < 3; ++a) faceArea_[static_cast<std::size_t>(a)] = cellVolume_ / spacing(a);
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

}  // namespace grainbridge::fluid
