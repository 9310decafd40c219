#pragma once
// The particles on the gas grid (Section 7.2.3): each particle's share of the cells
// (VolumeDeposition: the whole particle to the cell of its centre as the reference does, or its
// exact overlap with every cell), and from them per cell the solids fraction of Eq. 7.35, the
// solids velocity of Eq. 7.36 and the particles' Sauter mean diameter (the d_pm of Eq. 7.34 for
// several sizes; the one diameter otherwise). The shares are kept, so that what a cell's gas
// gives its particles and what they give back use the same weights: sum_i w_ic V_pi is the
// cell's solids volume, whatever the deposition.
#include <cstddef>
#include <vector>

#include "core/Types.hpp"
#include "core/grid/CellGrid.hpp"
#include "core/grid/CellShare.hpp"
#include "core/grid/SolidsCellAverages.hpp"
#include "engines/dem/Particles.hpp"
#include "engines/fluid/FlowState.hpp"

namespace grainbridge::tfdem {

using core::grid::VolumeDeposition;

struct ParticleDeposit {
  explicit ParticleDeposit(const fluid::StaggeredGrid& grid)
      : fraction(grid, 0.0), velocity(grid.paddedCount(), Vec3::Zero()), diameter(grid, 0.0) {}
  // Owned particle i's shares of the grid's cells, shares[offset[i]] to shares[offset[i + 1]],
  // each `cell` a padded index of the gas grid.
  std::vector<std::size_t> offset;
  core::grid::CellShares shares;
  fluid::CellField fraction;   // eps_s, Eq. 7.35 [-]
  std::vector<Vec3> velocity;  // v_s, Eq. 7.36, per padded cell [m/s]; zero without solids
  fluid::CellField diameter;   // Sauter mean of the cell's particles [m]; zero without solids
};

// The gas grid's interior as a core::grid::CellGrid, sharing one particle among its cells with the
// shares' cells as padded indices of the gas grid.
class GasGridCells {
 public:
  explicit GasGridCells(const fluid::StaggeredGrid& grid);
  // Replaces `out` with the particle's shares (none outside the grid).
  void shares(const Vec3& position, double radius, VolumeDeposition deposition, core::grid::CellShares& out) const;

 private:
  const fluid::StaggeredGrid* grid_;
  core::grid::CellGrid cells_;
};

// The owned particles of `particles` (frozen ones included: a fixed bed is a bed) on `grid`. A
// particle or the part of one outside the grid is not counted.
[[nodiscard]] ParticleDeposit depositParticles(const fluid::StaggeredGrid& grid, const dem::Particles& particles,
                                               VolumeDeposition deposition);

// Phase fields of the particles as the gas solver is given them: the fraction per cell, and on
// each face the solids-volume weighted mean of its two cells' velocities (zero between two cells
// without solids). Ghosts are left to Boundaries::apply.
void setParticlePhase(const ParticleDeposit& deposit, fluid::PhaseFields& phase);

// The particle volume 4/3 pi a^3.
[[nodiscard]] inline double particleVolume(double radius) { return 4.0 / 3.0 * M_PI * radius * radius * radius; }

}  // namespace grainbridge::tfdem
