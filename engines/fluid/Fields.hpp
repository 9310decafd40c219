#pragma once
// Fields over a staggered grid (StaggeredGrid.hpp): a CellField holds one value per cell centre,
// a FaceField one value per face normal to its axis (a velocity component), both over the padded
// index range (ghosts included), so a boundary condition is a write to a ghost entry and every
// stencil reads its neighbours without a bounds test.
#include <cstddef>
#include <vector>

#include "engines/fluid/StaggeredGrid.hpp"

namespace grainbridge::fluid {

// The storage and indexing both field kinds share: one value per padded grid position.
class PaddedValues {
 public:
  [[nodiscard]] double& operator()(int i, int j, int k) { return v_[grid_->index(i, j, k)]; }
  [[nodiscard]] double operator()(int i, int j, int k) const { return v_[grid_->index(i, j, k)]; }
  [[nodiscard]] double& operator[](std::size_t c) { return v_[c]; }
  [[nodiscard]] double operator[](std::size_t c) const { return v_[c]; }
  [[nodiscard]] const std::vector<double>& values() const { return v_; }
  [[nodiscard]] std::vector<double>& values() { return v_; }
  [[nodiscard]] const StaggeredGrid& grid() const { return *grid_; }

 protected:
  PaddedValues(const StaggeredGrid& grid, double value) : grid_(&grid), v_(grid.paddedCount(), value) {}

 private:
  const StaggeredGrid* grid_;
  std::vector<double> v_;
};

class CellField : public PaddedValues {
 public:
  explicit CellField(const StaggeredGrid& grid, double value = 0.0) : PaddedValues(grid, value) {}
};

// Values on the faces normal to `axis`; entry (i, j, k) is the high face of cell (i, j, k).
class FaceField : public PaddedValues {
 public:
  FaceField(const StaggeredGrid& grid, int axis, double value = 0.0) : PaddedValues(grid, value), axis_(axis) {}
  [[nodiscard]] int axis() const { return axis_; }

 private:
  int axis_;
};

}  // namespace grainbridge::fluid
