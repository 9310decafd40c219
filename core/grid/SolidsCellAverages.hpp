#pragma once
// Solid volume fraction and mean solids velocity per cell, Eqs. 7.35-7.36 of the reference:
//   eps_sm = sum_i V_pi / V_cell,   v_sm = sum_i v_pi V_pi / sum_i V_pi,
// for the particles of one solids phase (the caller passes that phase's particles). TF-DEM
// and extract share it. The reference sums the whole volume of each particle whose centre lies
// in the cell (CentreCell); ExactOverlap shares each sphere by its exact overlap volume with
// every cell (the extension the reference lists as future work), and is identical to CentreCell
// for a sphere that lies inside one cell.
#include <span>
#include <vector>

#include "core/Types.hpp"
#include "core/grid/CellGrid.hpp"
#include "core/grid/CellShare.hpp"

namespace grainbridge::core::grid {

enum class VolumeDeposition { CentreCell, ExactOverlap };

struct SolidsCellAverages {
  std::vector<double> solidFraction;  // eps_sm, Eq. 7.35 [-]
  std::vector<Vec3> velocity;         // v_sm, Eq. 7.36 [m/s]; zero in a cell without solids
};

// How one particle's volume is shared among the cells by `deposition` (CentreCell: all of it to
// the cell holding its centre, none outside the box), into `shares` (cleared first).
void particleCellShares(const CellGrid& grid, const Vec3& position, double radius, VolumeDeposition deposition,
                        CellShares& shares);

// positions, radii and velocities are per particle and of equal length (else grainbridge::Error).
// A particle outside a non-periodic box (or the part of it, for ExactOverlap) is not counted.
SolidsCellAverages averageSolidsOnCells(const CellGrid& grid, std::span<const Vec3> positions,
                                        std::span<const double> radii, std::span<const Vec3> velocities,
                                        VolumeDeposition deposition);

}  // namespace grainbridge::core::grid
