#pragma once
// The staggered Cartesian grid of the multiphase finite-volume framework (Section 3.3.1):
// scalars (pressure, volume fractions, granular temperature) live at cell centres, each velocity
// component on the faces normal to its axis, so the pressure difference of two neighbouring cells
// drives the velocity between them and no checkerboard field is a solution.
//
// Indexing follows MFiX's: every active axis has one layer of ghost cells on each side (i = -1
// and i = n), where boundary conditions are imposed (Eqs. 3.66-3.67 set a ghost value from its
// neighbour); the face (axis a, i, j, k) is the high face of cell (i, j, k) along a, so the
// faces of an axis run from i = -1 (the low boundary face is that of ghost cell -1) to i = n - 1
// (the high boundary face). A 2D grid (nz = 1) has no ghost layer along z and no z faces.
// Every field of the framework (CellField, FaceField) is stored over the padded index range
// in [k][j][i] order, the same layout as core's field frames.
#include <array>
#include <cstddef>
#include <vector>

#include "core/Types.hpp"
#include "core/data/FieldFrame.hpp"

namespace grainbridge::fluid {

class StaggeredGrid {
 public:
  // `geometry` gives the interior cells; nz = 1 makes the grid 2D (x-y). Throws
  // grainbridge::Error naming the axis for a non-positive cell count or spacing.
  explicit StaggeredGrid(core::data::GridGeometry geometry);

  [[nodiscard]] const core::data::GridGeometry& geometry() const { return geometry_; }
  [[nodiscard]] int dimensions() const { return geometry_.cells[2] == 1 ? 2 : 3; }
  [[nodiscard]] bool active(int axis) const { return axis < dimensions(); }
  [[nodiscard]] int cells(int axis) const { return geometry_.cells[static_cast<std::size_t>(axis)]; }
  [[nodiscard]] double spacing(int axis) const { return geometry_.spacing[axis]; }
  // Ghost layers along an axis: 1 where active, 0 along z in 2D.
  [[nodiscard]] int ghosts(int axis) const { return active(axis) ? 1 : 0; }

  // Number of cells with ghosts: the length of every field array.
  [[nodiscard]] std::size_t paddedCount() const { return padded_[0] * padded_[1] * padded_[2]; }
  // Flat index of cell (i, j, k), ghosts included (i from -ghosts to n - 1 + ghosts).
  [[nodiscard]] std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k + ghosts(2)) * padded_[1] + static_cast<std::size_t>(j + ghosts(1))) *
               padded_[0] +
           static_cast<std::size_t>(i + ghosts(0));
  }
  // The neighbour of flat index `c` one cell up (+1) or down (-1) along `axis`.
  [[nodiscard]] std::size_t neighbour(std::size_t c, int axis, int direction) const {
    return direction > 0 ? c + stride_[static_cast<std::size_t>(axis)] : c - stride_[static_cast<std::size_t>(axis)];
  }
  // (i, j, k) of a flat index: the inverse of index().
  // Looked up, not divided out: every assembly loop asks at every index.
  [[nodiscard]] std::array<int, 3> coordinates(std::size_t c) const { return coordinates_[c]; }
  [[nodiscard]] bool interior(std::size_t c) const { return interior_[c] != 0; }
  [[nodiscard]] bool interior(int i, int j, int k) const {
    return i >= 0 && i < cells(0) && j >= 0 && j < cells(1) && k >= 0 && k < cells(2);
  }

  [[nodiscard]] Vec3 cellCentre(int i, int j, int k) const;
  // Centre of face (axis, i, j, k): the high face of cell (i, j, k) along `axis`.
  [[nodiscard]] Vec3 faceCentre(int axis, int i, int j, int k) const;
  // Worked out once: the assembly loops ask for them at every face.
  [[nodiscard]] double cellVolume() const { return cellVolume_; }
  [[nodiscard]] double faceArea(int axis) const { return faceArea_[static_cast<std::size_t>(axis)]; }

 private:
  core::data::GridGeometry geometry_;
  std::array<std::size_t, 3> padded_{};
  std::array<std::size_t, 3> stride_{};
  std::vector<std::array<int, 3>> coordinates_;
  std::vector<char> interior_;
  double cellVolume_ = 0.0;
  std::array<double, 3> faceArea_{};
};

}  // namespace grainbridge::fluid
