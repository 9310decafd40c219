#include "engines/tfdem/ParticleDeposit.hpp"

namespace grainbridge::tfdem {

namespace {

core::grid::CellGrid interiorCells(const fluid::StaggeredGrid& grid) {
  const auto& g = grid.geometry();
  const Vec3 extent(g.cells[0] * g.spacing.x(), g.cells[1] * g.spacing.y(), g.cells[2] * g.spacing.z());
  return {g.origin, g.origin + extent, g.cells};
}

}  // namespace

GasGridCells::GasGridCells(const fluid::StaggeredGrid& grid) : grid_(&grid), cells_(interiorCells(grid)) {}

void GasGridCells::shares(const Vec3& position, double radius, VolumeDeposition deposition,
                          core::grid::CellShares& out) const {
  core::grid::particleCellShares(cells_, position, radius, deposition, out);
  for (core::grid::CellShare& share : out) {
    const core::grid::CellIndex at = cells_.cellIndex(share.cell);
    share.cell = grid_->index(at.i, at.j, at.k);
  }
}

ParticleDeposit depositParticles(const fluid::StaggeredGrid& grid, const dem::Particles& particles,
                                 VolumeDeposition deposition) {
  const GasGridCells cells(grid);
  ParticleDeposit out(grid);
  const std::size_t n = particles.nOwned;
  out.offset.assign(n + 1, 0);
  std::vector<double> volume(grid.paddedCount(), 0.0), volumeOverDiameter(grid.paddedCount(), 0.0);
  core::grid::CellShares one;
  for (std::size_t i = 0; i < n; ++i) {
    cells.shares(particles.x[i], particles.radius[i], deposition, one);
    const double vp = particleVolume(particles.radius[i]);
    for (const core::grid::CellShare& share : one) {
      out.shares.push_back(share);
      volume[share.cell] += share.fraction * vp;
      volumeOverDiameter[share.cell] += share.fraction * vp / (2.0 * particles.radius[i]);
      out.velocity[share.cell] += share.fraction * vp * particles.v[i];
    }
    out.offset[i + 1] = out.shares.size();
  }
  const double cellVolume = grid.cellVolume();
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (!(volume[c] > 0.0)) continue;
    out.fraction[c] = volume[c] / cellVolume;  // Eq. 7.35
    out.velocity[c] /= volume[c];              // Eq. 7.36
    out.diameter[c] = volume[c] / volumeOverDiameter[c];
  }
  return out;
}

void setParticlePhase(const ParticleDeposit& deposit, fluid::PhaseFields& phase) {
  const fluid::StaggeredGrid& grid = phase.fraction.grid();
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (grid.interior(c)) phase.fraction[c] = deposit.fraction[c];
  }
  for (int a = 0; a < grid.dimensions(); ++a) {
    fluid::FaceField& u = phase.velocity[static_cast<std::size_t>(a)];
    for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
      if (grid.coordinates(f)[static_cast<std::size_t>(a)] == grid.cells(a)) continue;  // the last ghost: no face
      const std::size_t E = grid.neighbour(f, a, +1);
      const double wP = deposit.fraction[f], wE = deposit.fraction[E];
      u[f] = wP + wE > 0.0 ? (wP * deposit.velocity[f][a] + wE * deposit.velocity[E][a]) / (wP + wE) : 0.0;
    }
  }
}

}  // namespace grainbridge::tfdem
