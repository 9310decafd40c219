#include "core/grid/SolidsCellAverages.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "core/grid/CellShare.hpp"
#include "core/grid/SphereCellOverlap.hpp"

namespace grainbridge::core::grid {

void particleCellShares(const CellGrid& grid, const Vec3& position, double radius, VolumeDeposition deposition,
                        CellShares& shares) {
  if (deposition == VolumeDeposition::CentreCell) {
    // Eq. 7.35: the whole particle goes to the cell holding its centre.
    shares.clear();
    if (const auto cell = grid.cellOf(position)) shares.push_back({grid.flatIndex(*cell), 1.0});
  } else {
    sphereCellShares(grid, position, radius, shares);
  }
}

SolidsCellAverages averageSolidsOnCells(const CellGrid& grid, std::span<const Vec3> positions,
                                        std::span<const double> radii, std::span<const Vec3> velocities,
                                        VolumeDeposition deposition) {
  if (radii.size() != positions.size() || velocities.size() != positions.size()) {
    throw Error("solids cell averages: " + std::to_string(positions.size()) + " positions, " +
                std::to_string(radii.size()) + " radii and " + std::to_string(velocities.size()) +
                " velocities; expected one of each per particle");
  }
  const std::size_t cells = grid.cellCount();
  std::vector<double> volume(cells, 0.0);
  std::vector<Vec3> volumeVelocity(cells, Vec3::Zero());
  CellShares shares;
  for (std::size_t p = 0; p < positions.size(); ++p) {
    const double vp = 4.0 / 3.0 * M_PI * radii[p] * radii[p] * radii[p];
    particleCellShares(grid, positions[p], radii[p], deposition, shares);
    for (const auto& s : shares) {
      volume[s.cell] += vp * s.fraction;
      volumeVelocity[s.cell] += vp * s.fraction * velocities[p];
    }
  }
  SolidsCellAverages out;
  out.solidFraction.resize(cells);
  out.velocity.assign(cells, Vec3::Zero());
  const double cellVolume = grid.cellVolume();
  for (std::size_t c = 0; c < cells; ++c) {
    out.solidFraction[c] = volume[c] / cellVolume;
    // Eq. 7.36: volume-weighted mean velocity.
    if (volume[c] > 0.0) out.velocity[c] = volumeVelocity[c] / volume[c];
  }
  return out;
}

}  // namespace grainbridge::core::grid
