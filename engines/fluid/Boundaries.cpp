#include "engines/fluid/Boundaries.hpp"

#include <algorithm>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::fluid {

namespace {

const char* sideName(int side) {
  static const char* names[] = {"x low", "x high", "y low", "y high", "z low", "z high"};
  return side >= 0 && side < 6 ? names[side] : "unknown";
}

}  // namespace

std::array<int, 2> tangentialAxes(int axis) {
  return axis == 0 ? std::array<int, 2>{1, 2} : axis == 1 ? std::array<int, 2>{0, 2} : std::array<int, 2>{0, 1};
}

Boundaries::Boundaries(const StaggeredGrid& grid, std::vector<BoundaryPatch> patches, std::size_t phaseCount)
    : grid_(&grid),
      patches_(std::move(patches)),
      kind_(grid.paddedCount(), BoundaryKind::NoSlipWall),
      patchOf_(grid.paddedCount(), -1) {
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (grid.interior(c)) kind_[c] = BoundaryKind::Interior;
  }
  for (int axis = 0; axis < grid.dimensions(); ++axis) {
    const auto t = tangentialAxes(axis);
    for (int direction : {-1, +1}) {
      for (int u = 0; u < grid.cells(t[0]); ++u) {
        for (int v = 0; v < grid.cells(t[1]); ++v) {
          std::array<int, 3> at{};
          at[static_cast<std::size_t>(axis)] = direction < 0 ? -1 : grid.cells(axis);
          at[static_cast<std::size_t>(t[0])] = u;
          at[static_cast<std::size_t>(t[1])] = v;
          const std::size_t g = grid.index(at[0], at[1], at[2]);
          ghosts_.push_back({g, grid.neighbour(g, axis, -direction), axis, direction});
        }
      }
    }
  }
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    BoundaryPatch& patch = patches_[p];
    const std::string where = "boundary patch " + std::to_string(p) + " (" + sideName(patch.side) + ")";
    if (patch.side < 0 || patch.side > 5) throw Error(where + ": side must be 0..5");
    const int axis = patch.side / 2;
    if (!grid.active(axis)) throw Error(where + ": the grid is 2D, it has no z sides");
    const auto t = tangentialAxes(axis);
    for (int q = 0; q < 2; ++q) {
      const int n = grid.cells(t[static_cast<std::size_t>(q)]);
      int& from = patch.from[static_cast<std::size_t>(q)];
      int& to = patch.to[static_cast<std::size_t>(q)];
      if (to < 0) {
        from = 0;
        to = n;
      }
      if (from < 0 || to > n || from >= to) {
        throw Error(where + ": cells [" + std::to_string(from) + ", " + std::to_string(to) + ") along its " +
                    std::string(1, "xyz"[t[static_cast<std::size_t>(q)]]) + " axis are not on the side (0.." +
                    std::to_string(n) + ")");
      }
    }
    const bool carriesPhases = patch.kind == BoundaryKind::VelocityInlet || patch.kind == BoundaryKind::PressureOutlet;
    if (patch.kind == BoundaryKind::PressureOutlet && patch.phases.empty()) {
      patch.phases.assign(phaseCount, PhaseInflow{});
      patch.phases[0].fraction = 1.0;  // gas alone flows back in unless told otherwise
    }
    if (carriesPhases && patch.phases.size() != phaseCount) {
      throw Error(where + ": gives " + std::to_string(patch.phases.size()) + " phase states for " +
                  std::to_string(phaseCount) + " phases");
    }
    for (const Ghost& ghost : ghosts_) {
      if (ghost.axis != axis || (ghost.direction < 0) != (patch.side % 2 == 0)) continue;
      const auto at = grid.coordinates(ghost.cell);
      const int u = at[static_cast<std::size_t>(t[0])], v = at[static_cast<std::size_t>(t[1])];
      if (u < patch.from[0] || u >= patch.to[0] || v < patch.from[1] || v >= patch.to[1]) continue;
      if (patchOf_[ghost.cell] >= 0) {
        throw Error(where + ": overlaps boundary patch " + std::to_string(patchOf_[ghost.cell]));
      }
      patchOf_[ghost.cell] = static_cast<int>(p);
      kind_[ghost.cell] = patch.kind;
    }
  }
  // Which faces carry unknowns and which let mass through, once: every assembly asks per face.
  for (int axis = 0; axis < 3; ++axis) {
    auto& solved = solved_[static_cast<std::size_t>(axis)];
    auto& open = open_[static_cast<std::size_t>(axis)];
    solved.assign(grid.paddedCount(), 0);
    open.assign(grid.paddedCount(), 0);
    if (!grid.active(axis)) continue;
    for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
      solved[f] = faceIsSolved(axis, f) ? 1 : 0;
      open[f] = faceIsOpen(axis, f) ? 1 : 0;
    }
  }
}

bool Boundaries::hasOutlet() const {
  return std::any_of(patches_.begin(), patches_.end(),
                     [](const BoundaryPatch& p) { return p.kind == BoundaryKind::PressureOutlet; });
}

const BoundaryPatch* Boundaries::outletOfFace(int axis, std::size_t face, int& inward) const {
  if (!openFace(axis, face)) return nullptr;
  const bool lowSide = !grid_->interior(face);
  const std::size_t ghost = lowSide ? face : grid_->neighbour(face, axis, +1);
  if (grid_->interior(ghost) || kind_[ghost] != BoundaryKind::PressureOutlet) return nullptr;
  inward = lowSide ? +1 : -1;
  return &patches_[static_cast<std::size_t>(patchOf_[ghost])];
}

bool Boundaries::faceIsSolved(int axis, std::size_t face) const {
  const auto at = grid_->coordinates(face);
  for (int b = 0; b < 3; ++b) {
    if (b != axis && (at[static_cast<std::size_t>(b)] < 0 || at[static_cast<std::size_t>(b)] >= grid_->cells(b)))
      return false;
  }
  const int i = at[static_cast<std::size_t>(axis)], n = grid_->cells(axis);
  if (i >= 0 && i <= n - 2) return true;
  if (i == -1) return kind_[face] == BoundaryKind::PressureOutlet;
  if (i == n - 1) return kind_[grid_->neighbour(face, axis, +1)] == BoundaryKind::PressureOutlet;
  return false;
}

bool Boundaries::faceIsOpen(int axis, std::size_t face) const {
  const auto at = grid_->coordinates(face);
  const int i = at[static_cast<std::size_t>(axis)], n = grid_->cells(axis);
  if (i < -1 || i > n - 1) return false;
  for (int b = 0; b < 3; ++b) {
    if (b != axis && (at[static_cast<std::size_t>(b)] < 0 || at[static_cast<std::size_t>(b)] >= grid_->cells(b)))
      return false;
  }
  if (i >= 0 && i <= n - 2) return true;
  const BoundaryKind k = i == -1 ? kind_[face] : kind_[grid_->neighbour(face, axis, +1)];
  return k == BoundaryKind::VelocityInlet || k == BoundaryKind::PressureOutlet;
}

namespace {

// The ratio r = v_ghost / v_interior that gives a tangential face at a wall the traction
// -c v_wall, v_wall = (v_ghost + v_interior) / 2, against the viscous flux
// mu (v_ghost - v_interior) / h the momentum stencil takes through the wall:
//   r = (mu / h - c / 2) / (mu / h + c / 2),
// -1 (no slip) as c -> infinity, +1 (free slip) at c = 0. mu and c are the means over the face's
// two cells inside the domain (its control volume's).
double partialSlipRatio(const StaggeredGrid& grid, const PhaseProperties& props, std::size_t interiorFace, int axis,
                        int along) {
  const std::size_t other = grid.neighbour(interiorFace, along, +1);
  const bool both = grid.interior(other);
  const double mu = both ? 0.5 * (props.shearViscosity[interiorFace] + props.shearViscosity[other])
                         : props.shearViscosity[interiorFace];
  const double c = both ? 0.5 * (props.wallSlipCoefficient[interiorFace] + props.wallSlipCoefficient[other])
                        : props.wallSlipCoefficient[interiorFace];
  const double conductance = mu / grid.spacing(axis);
  if (!(conductance + 0.5 * c > 0.0)) return 1.0;  // nothing to transmit a traction: free slip
  return (conductance - 0.5 * c) / (conductance + 0.5 * c);
}

}  // namespace

void Boundaries::apply(FlowState& state, const FlowProperties* properties) const {
  const std::size_t phaseCount = state.phases.size();
  for (const Ghost& ghost : ghosts_) {
    const std::size_t g = ghost.cell, in = ghost.inner;
    const BoundaryKind k = kind_[g];
    const BoundaryPatch* patch = patchOf_[g] >= 0 ? &patches_[static_cast<std::size_t>(patchOf_[g])] : nullptr;
    const std::size_t face = ghost.direction < 0 ? g : in;  // the boundary face's storage
    const int a = ghost.axis;
    state.pressure[g] = k == BoundaryKind::PressureOutlet ? patch->pressure : state.pressure[in];
    const bool gasLeaves = state.phases[0].velocity[static_cast<std::size_t>(a)][face] * ghost.direction >= 0.0;
    for (std::size_t m = 0; m < phaseCount; ++m) {
      PhaseFields& phase = state.phases[m];
      phase.granularTemperature[g] = k == BoundaryKind::VelocityInlet && patch->phases[m].granularTemperature >= 0.0
                                         ? patch->phases[m].granularTemperature
                                         : phase.granularTemperature[in];
      FaceField& normal = phase.velocity[static_cast<std::size_t>(a)];
      const PhaseProperties* slip = properties != nullptr && properties->phases[m].partialSlipWalls
                                        ? &properties->phases[m]
                                        : nullptr;
      switch (k) {
        case BoundaryKind::VelocityInlet:
          phase.fraction[g] = patch->phases[m].fraction;
          normal[face] = patch->phases[m].velocity[a];
          break;
        case BoundaryKind::PressureOutlet: {
          // The gas: leaving, the interior's fraction; entering, the backflow state's. A solids
          // phase's ghost repeats the interior whichever way it moves, so that the outlet face's
          // momentum coefficients (its mean fraction) do not jump when a phase hovering at the
          // outlet turns: that flip kept the chaff at the combine's top outlet from converging.
          // What a solids phase brings back in is the backflow state's all the same (massFluxes).
          // Never below the backflow state's, though: a ghost as empty as an empty interior
          // gave the face no solids to move, so a nonzero backflow never came in (issue 56);
          // the larger of the two does not depend on the direction, so nothing flips.
          const double backflow = patch->phases[m].fraction;
          if (m > 0) {
            phase.fraction[g] = backflow > 0.0 ? std::max(phase.fraction[in], backflow) : phase.fraction[in];
          } else {
            phase.fraction[g] = gasLeaves ? phase.fraction[in] : backflow;
          }
          break;
        }
        default:
          phase.fraction[g] = phase.fraction[in];
          normal[face] = 0.0;
          break;
      }
      // Past a high-side boundary face, the face of the ghost continues it (zero gradient).
      if (ghost.direction > 0) normal[g] = normal[face];
      for (int b = 0; b < grid_->dimensions(); ++b) {
        if (b == a) continue;
        FaceField& tangential = phase.velocity[static_cast<std::size_t>(b)];
        for (const std::size_t f : {g, grid_->neighbour(g, b, -1)}) {
          const std::size_t fin = grid_->neighbour(f, a, -ghost.direction);
          switch (k) {
            case BoundaryKind::NoSlipWall:
              if (slip != nullptr && grid_->interior(fin)) {
                tangential[f] = partialSlipRatio(*grid_, *slip, fin, a, b) * tangential[fin];
              } else {
                tangential[f] = -tangential[fin];
              }
              break;
            case BoundaryKind::VelocityInlet:
              tangential[f] = 2.0 * patch->phases[m].velocity[b] - tangential[fin];
              break;
            default:
              tangential[f] = tangential[fin];
              break;  // free slip, outlet
          }
        }
      }
    }
  }
}

void Boundaries::copyToGhosts(CellField& field) const {
  for (const Ghost& ghost : ghosts_) field[ghost.cell] = field[ghost.inner];
}

}  // namespace grainbridge::fluid
