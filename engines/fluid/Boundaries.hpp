#pragma once
// Boundary conditions of the staggered grid (Section 3.3.2.2), imposed on the ghost layer as
// MFiX does: every ghost cell belongs to one patch of its side, and `apply` writes the values
// that the patch's rule gives before each assembly:
//   no-slip wall   normal velocity 0 on the wall face; tangential ghost = -interior (Eq. 3.67),
//                  so the wall value, the mean of the two, is zero;
//   free-slip wall normal velocity 0; tangential ghost = interior (Eq. 3.66), no shear;
//   velocity inlet each phase's fraction in the ghost and its velocity on the face (a uniform
//                  inflow, or a jet: a patch covering part of a side, aligned with the faces);
//                  tangential ghost = 2 v_in - interior, so the face value is the inflow's;
//   pressure outlet the ghost holds the outlet pressure; the normal velocity on the outlet face is
//                  solved from momentum; the gas leaving takes the interior's fraction, flowing
//                  back in the patch's backflow state's; a solids phase's ghost repeats the
//                  interior either way, and what it carries back in is the backflow state's
//                  (massFluxes), so its face coefficients do not jump when it turns.
// Sides no patch covers are no-slip walls. A phase whose properties ask for partial slip
// (PhaseProperties::partialSlipWalls, Johnson-Jackson) has at no-slip wall patches the Robin
// ghost value that gives the wall traction -c v_slip (Eq. 5.8). A granular temperature's ghosts
// repeat the interior (no conduction through the side), except at an inlet that states the
// temperature its inflow carries; the wall's energy flux (Eq. 5.9) is the granular-energy
// equation's own boundary term.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "engines/fluid/FlowState.hpp"
#include "engines/fluid/PhaseProperties.hpp"

namespace grainbridge::fluid {

enum class BoundaryKind : unsigned char { Interior, NoSlipWall, FreeSlipWall, VelocityInlet, PressureOutlet };

// The six sides of the domain: 2 * axis for the low side, 2 * axis + 1 for the high side.
enum Side : int { XLow = 0, XHigh = 1, YLow = 2, YHigh = 3, ZLow = 4, ZHigh = 5 };

// The two axes along a side normal to `axis`, in x, y, z order: the order of a patch's ranges.
[[nodiscard]] std::array<int, 2> tangentialAxes(int axis);

struct PhaseInflow {
  double fraction = 0.0;         // eps_m [-]
  Vec3 velocity = Vec3::Zero();  // v_m [m/s]
  // The granular temperature the inflow carries [m^2/s^2] (MFiX's BC_THETA_M): the inlet ghost's
  // theta, which the granular-energy equation convects and conducts in. Negative: none given, the
  // ghost repeats the interior (the inflow carries the theta of the cell it enters).
  double granularTemperature = -1.0;
};

struct BoundaryPatch {
  BoundaryKind kind = BoundaryKind::NoSlipWall;
  int side = YLow;
  // The cells of the side the patch covers, along its first and second tangential axes (x before
  // y before z), as half-open ranges of cell indices; {0, -1} means the whole side.
  std::array<int, 2> from{0, 0};
  std::array<int, 2> to{-1, -1};
  std::vector<PhaseInflow> phases;  // inlet: the inflow of each phase; outlet: the backflow state
  double pressure = 0.0;            // outlet [Pa]
};

class Boundaries {
 public:
  // Throws grainbridge::Error naming the patch (by its position in `patches`) when it lies on an
  // inactive side (z in 2D), off the side, overlaps another, or gives a phase count other than
  // `phaseCount` (inlets and outlets).
  Boundaries(const StaggeredGrid& grid, std::vector<BoundaryPatch> patches, std::size_t phaseCount);

  [[nodiscard]] const StaggeredGrid& grid() const { return *grid_; }
  [[nodiscard]] const std::vector<BoundaryPatch>& patches() const { return patches_; }
  // The kind of a padded cell: Interior for an interior cell, the patch's for a ghost of a side
  // (corner ghosts, which no stencil reads, are walls).
  [[nodiscard]] BoundaryKind kind(std::size_t cell) const { return kind_[cell]; }
  // The index in patches() of the patch a ghost cell belongs to; -1 for interior and corner cells
  // and for ghosts of sides no patch covers (walls).
  [[nodiscard]] int patchOf(std::size_t cell) const { return patchOf_[cell]; }
  [[nodiscard]] bool hasOutlet() const;

  // Whether the face (axis, face) carries an unknown of the momentum equation of `axis`: an
  // interior face, or the face of a pressure outlet.
  [[nodiscard]] bool solvedFace(int axis, std::size_t face) const {
    return solved_[static_cast<std::size_t>(axis)][face] != 0;
  }
  // The pressure outlet whose boundary face (axis, face) is, or null; `inward` is +1 when a
  // positive velocity on it enters the domain (a low side), -1 otherwise.
  [[nodiscard]] const BoundaryPatch* outletOfFace(int axis, std::size_t face, int& inward) const;
  // Whether the face (axis, face) lets mass through: not a wall face.
  [[nodiscard]] bool openFace(int axis, std::size_t face) const {
    return open_[static_cast<std::size_t>(axis)][face] != 0;
  }

  // Writes the ghost values of `state`: fractions and pressure in ghost cells, the normal velocity
  // on wall and inlet faces, the tangential ghost velocities, and past an outlet face the
  // zero-gradient continuation of its velocity. `properties`, when given, supply the partial-slip
  // walls' coefficients (their viscosity and wallSlipCoefficient, ghosts copied).
  void apply(FlowState& state, const FlowProperties* properties = nullptr) const;
  // Copies each ghost cell's interior neighbour into it: a cell property (viscosity, density)
  // that the stencils read on the boundary.
  void copyToGhosts(CellField& field) const;

 private:
  const StaggeredGrid* grid_;
  std::vector<BoundaryPatch> patches_;
  std::vector<BoundaryKind> kind_;
  std::vector<int> patchOf_;  // the patch index of a ghost cell, -1 elsewhere
  struct Ghost {
    std::size_t cell;   // the ghost
    std::size_t inner;  // its interior neighbour
    int axis;           // the side's normal axis
    int direction;      // -1 on the low side, +1 on the high side
  };
  std::vector<Ghost> ghosts_;
  [[nodiscard]] bool faceIsSolved(int axis, std::size_t face) const;
  [[nodiscard]] bool faceIsOpen(int axis, std::size_t face) const;
  std::array<std::vector<char>, 3> solved_, open_;  // per axis and padded face, from the two above
};

}  // namespace grainbridge::fluid
