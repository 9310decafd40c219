#pragma once
// Coarse graining of one particle frame on a grid (Eq. 2.3 of the reference, Section 8.2.1.3's
// "coarse-graining function with width w"): solid fraction, density, velocity and granular
// temperature per species and in total, the stress tensor with its kinetic and contact parts,
// and the contact statistics of Chapter 7. Reads the frame through core's data model only.
//
// Definitions (see CoarseFields.hpp for units):
//  - phi_i(c): the share of particle i in cell c by the kernel (CoarseGrainingKernel.hpp);
//    rho_c = sum m_i phi_i(c) / V_c, solid fraction sum V_i phi_i(c) / V_c.
//  - Peculiar velocity v'_i = v_i - u_LE(r_i) (StreamingProfile.hpp; u_LE = 0 without shear),
//    local mean u'_c = sum m v' phi / sum m phi, fluctuation C_i = v'_i - u'_c at the field cell.
//  - Kinetic stress sum m_i C_i C_i phi_i(c) / V_c; T_c = tr / (3 rho_c) (Eq. 3.38).
//  - Contact stress: Eq. 2.3's sum over i and j != i of 1/2 r_ij F_ij counts each stored pair
//    twice with the same product, so each contact contributes its full r_ij F_ij (branch
//    r_i - r_j times the force on i), spread along the segment from r_i to r_j by the kernel's
//    segment shares. A wall contact is a contact with the wall as j at the contact point: full
//    (r_i - point) F along the segment from r_i to the point. Summed over a periodic box this is
//    the whole-domain stress the DEM engine prints.
#include <cstddef>
#include <optional>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"
#include "core/grid/CellGrid.hpp"
#include "core/grid/CellShare.hpp"
#include "extract/coarse/CoarseFields.hpp"
#include "extract/coarse/CoarseGrainingKernel.hpp"
#include "extract/coarse/FrameSpecies.hpp"
#include "extract/coarse/ParticleContacts.hpp"

namespace grainbridge::extract::coarse {

// CellGrid::overDomain(frame.domain, counts) gives a grid over the whole box with the domain's
// periodicity; a grid over a sub-region (not periodic) drops what lies outside it.
// Throws grainbridge::Error for an inconsistent frame, a contact naming an unknown particle, a
// smooth kernel narrower than the cells, or a grid periodic on an axis where it does not span
// the periodic domain. Under Lees-Edwards the frame's offset is applied to the grid's images.
CoarseFields coarseGrain(const core::data::ParticleFrame& frame, const core::grid::CellGrid& grid,
                         const CoarseGrainingKernel& kernel);

// Coarse graining of frame after frame (the same results as coarseGrain) that keeps its cell
// arrays, and the fields it returns, from one call to the next: on a large grid, allocating and
// zero-filling some 60 MB of fresh cell arrays per frame cost as much as the coarse graining
// itself (page faults). It also remembers which cells the last frame reached, so the next one
// clears and finalises only those and its own (the empty space above a bed costs nothing).
// Not thread-safe; one per thread.
class CoarseGrainer {
 public:
  // As coarseGrain. The fields are overwritten by the next call.
  const CoarseFields& operator()(const core::data::ParticleFrame& frame, const core::grid::CellGrid& grid,
                                 const CoarseGrainingKernel& kernel);
  // Moves the last fields out (the next call allocates new ones). Needs a call first.
  CoarseFields release();

 private:
  // What the cell arrays hold depends on; any change starts them afresh.
  struct Layout {
    std::size_t cells = 0, species = 0;
    bool sheared = false, drag = false;
    bool operator==(const Layout&) const = default;
  };
  // Sizes the fields for the grid and zeroes the arrays the passes accumulate into.
  CoarseFields& prepare(const core::grid::CellGrid& grid, const CoarseGrainingKernel& kernel, const Layout& layout);

  std::optional<CoarseFields> fields_;
  std::optional<Layout> layout_;
  // Per frame: id lookup, contacts per particle, species (kept for their storage).
  ParticleIndex index_;
  ParticleContacts contacts_;
  FrameSpecies species_;
  // Every cell outside [dirtyBegin_, dirtyEnd_) holds the values of an empty cell in every
  // array (zeros; contactToDragRatio -1): the cells the last frame reached lie inside.
  std::size_t dirtyBegin_ = 0, dirtyEnd_ = 0;
  // Per particle: the cell holding its centre (npos outside the grid), and for the kernels that
  // spread a particle over several cells, its shares (shares_[offset_[i]] .. [offset_[i + 1]]).
  std::vector<std::size_t> centreCell_, offset_;
  core::grid::CellShares shares_, one_;
  // Per cell: mean peculiar velocity of all and of each species (needed only under shear:
  // otherwise it is the mean velocity), particles in contact, sums of contact and drag forces.
  std::vector<Vec3> meanPeculiar_;
  std::vector<std::vector<Vec3>> speciesMeanPeculiar_;
  std::vector<double> inContact_;
  std::vector<Vec3> contactForce_, drag_;
};

}  // namespace grainbridge::extract::coarse
