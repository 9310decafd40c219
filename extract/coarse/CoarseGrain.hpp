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
#include "core/data/ParticleFrame.hpp"
#include "core/grid/CellGrid.hpp"
#include "extract/coarse/CoarseFields.hpp"
#include "extract/coarse/CoarseGrainingKernel.hpp"

namespace grainbridge::extract::coarse {

// CellGrid::overDomain(frame.domain, counts) gives a grid over the whole box with the domain's
// periodicity; a grid over a sub-region (not periodic) drops what lies outside it.
// Throws grainbridge::Error for an inconsistent frame, a contact naming an unknown particle, a
// smooth kernel narrower than the cells, or a grid periodic on an axis where it does not span
// the periodic domain. Under Lees-Edwards the frame's offset is applied to the grid's images.
CoarseFields coarseGrain(const core::data::ParticleFrame& frame, const core::grid::CellGrid& grid,
                         const CoarseGrainingKernel& kernel);

}  // namespace grainbridge::extract::coarse
