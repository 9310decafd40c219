#pragma once
// Shares a particle (a point) or a contact (a segment) among cells with a smooth kernel:
// cell c receives phi(x_c - r_i) for a particle, and the line integral
//   L(x_c) = integral_0^1 phi(x_c - r_i + s r_ij) ds
// for a contact with branch r_ij = r_i - r_j (the segment from r_i to r_j), which is how the
// contact part of Eq. 2.3 is spread along the contact line.
//
// Discrete normalisation: the values over the cell lattice are divided by their sum, so every
// particle and contact deposits exactly 1 (the integral of the coarse-grained solid fraction is
// the total particle volume to round-off, and a homogeneous lattice gives the applied stress in
// every interior cell). The sum runs over the infinite lattice of cell centres: periodic images
// fold back into the box (Lees-Edwards displaced across y) and every image is summed (the
// minimum image when the cutoff is below half the box), while cells beyond a non-periodic face
// count in the sum but are dropped, so a kernel cut by a non-periodic boundary loses weight
// rather than piling it into the edge cells. With a width of a cell or more the sum differs from
// the continuous integral 1 / cell volume by well under a percent.
#include "core/Types.hpp"
#include "core/grid/CellGrid.hpp"
#include "core/grid/CellShare.hpp"
#include "core/grid/SmoothingKernel.hpp"

namespace grainbridge::core::grid {

// integral_0^1 phi(|x - start - s (end - start)|) ds, exactly: the segment is clipped to the
// kernel's support ball around x and the kernel's closed-form line integral taken over the rest.
double kernelSegmentIntegral(const SmoothingKernel& kernel, const Vec3& x, const Vec3& start, const Vec3& end);

// Throws grainbridge::Error when some point of the box could have no cell centre within the
// kernel's cutoff (cutoff <= half the cell diagonal): it would deposit nothing.
void checkKernelResolvesGrid(const CellGrid& grid, const SmoothingKernel& kernel);

// Replaces out with the normalised shares of a particle at point (see above).
void kernelPointShares(const CellGrid& grid, const SmoothingKernel& kernel, const Vec3& point, CellShares& out);

// Replaces out with the normalised shares of the segment from start to end.
void kernelSegmentShares(const CellGrid& grid, const SmoothingKernel& kernel, const Vec3& start, const Vec3& end,
                         CellShares& out);

}  // namespace grainbridge::core::grid
