#include "engines/fluid/BoundaryFlow.hpp"

namespace grainbridge::fluid {

std::vector<PatchFlow> patchFlows(const std::array<FaceField, 3>& flux, const Boundaries& boundaries) {
  const StaggeredGrid& grid = boundaries.grid();
  std::vector<PatchFlow> flows(boundaries.patches().size());
  for (int a = 0; a < grid.dimensions(); ++a) {
    const FaceField& F = flux[static_cast<std::size_t>(a)];
    for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
      if (!boundaries.openFace(a, f)) continue;
      // A boundary face has a ghost on one side: the low side's face is stored at its ghost, the
      // high side's at the last interior cell.
      const std::size_t high = grid.neighbour(f, a, +1);
      const bool lowSide = !grid.interior(f);
      if (!lowSide && grid.interior(high)) continue;  // an interior face
      const int patch = boundaries.patchOf(lowSide ? f : high);
      if (patch < 0) continue;
      const double inward = lowSide ? F[f] : -F[f];
      PatchFlow& flow = flows[static_cast<std::size_t>(patch)];
      if (inward >= 0.0) {
        flow.in += inward;
      } else {
        flow.out -= inward;
      }
    }
  }
  return flows;
}

PatchFlow total(const std::vector<PatchFlow>& patches) {
  PatchFlow sum;
  for (const PatchFlow& p : patches) {
    sum.in += p.in;
    sum.out += p.out;
  }
  return sum;
}

double superficialGasVelocity(const std::vector<BoundaryPatch>& patches, const core::data::GridGeometry& geometry,
                              VerticalAxis vertical) {
  const double bottom = bottomArea(geometry, vertical);
  double velocity = 0.0;
  for (const BoundaryPatch& patch : patches) {
    if (patch.kind != BoundaryKind::VelocityInlet || patch.phases.empty()) continue;
    const int axis = patch.side / 2;
    // The patch's area as bottomArea forms the bottom's, extent by extent in x, y, z order, so
    // that a whole bottom patch's ratio to it is 1 without round-off.
    double area = 1.0;
    const auto tangential = tangentialAxes(axis);
    for (std::size_t q = 0; q < 2; ++q) {
      const auto t = static_cast<std::size_t>(tangential[q]);
      const int cells = patch.to[q] < 0 ? geometry.cells[t] : patch.to[q] - patch.from[q];
      area *= cells * geometry.spacing[static_cast<Eigen::Index>(t)];
    }
    const double inward = patch.side % 2 == 0 ? 1.0 : -1.0;  // velocities point along the axis
    const PhaseInflow& gas = patch.phases.front();
    velocity += gas.fraction * (inward * gas.velocity[axis]) * (area / bottom);
  }
  return velocity;
}

double heldMass(const CellField& fraction, const CellField& density) {
  const StaggeredGrid& grid = fraction.grid();
  double mass = 0.0;
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        mass += density[c] * fraction[c];
      }
    }
  }
  return mass * grid.cellVolume();
}

}  // namespace grainbridge::fluid
