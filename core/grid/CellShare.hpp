#pragma once
// How one particle (or one contact segment) is shared among the cells of a CellGrid: the
// fraction of it each cell receives. A deposited field is
//   field[cell] = sum over objects of quantity * fraction / cell volume,
// so fractions summing to 1 over the grid conserve the quantity exactly (the integral of the
// coarse-grained solid fraction is the total particle volume).
#include <cstddef>
#include <vector>

namespace grainbridge::core::grid {

struct CellShare {
  std::size_t cell = 0;   // flat [k][j][i] index
  double fraction = 0.0;  // dimensionless share of the object held by this cell
};

using CellShares = std::vector<CellShare>;

}  // namespace grainbridge::core::grid
