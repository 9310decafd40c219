#pragma once
// The primary image of a particle of a Lees-Edwards box: the copy of it inside the box along
// the gradient axis y (an image above is displaced by the offset along x and streams faster by
// shearRate L_y, so crossing the upper face takes x - offset and v_x - shearRate L_y) and along
// the flow axis x. The engines move a particle into the box only when they rebuild their
// neighbour lists (grainbridge when the skin runs out, LAMMPS at its reneighbouring), so between
// builds a particle can sit outside the box as another image, with another lab-frame velocity.
// Frames and energies show this image, so that what is written does not depend on when either
// engine last rebuilt (grainbridge's lists now last hundreds of steps in a sheared box).
#include <cmath>

#include "core/Types.hpp"

namespace grainbridge::dem {

inline void toPrimaryImage(Vec3& x, Vec3& v, const Vec3& lo, const Vec3& hi, double offset, double shearRate) {
  const double ly = hi[1] - lo[1];
  const double images = std::floor((x[1] - lo[1]) / ly);  // 0 inside, +1 above, -1 below
  if (images != 0.0) {
    x[1] -= images * ly;
    x[0] -= images * offset;
    v[0] -= images * shearRate * ly;
  }
  const double lx = hi[0] - lo[0];
  x[0] -= std::floor((x[0] - lo[0]) / lx) * lx;
}

}  // namespace grainbridge::dem
