#pragma once
// The velocity profile Lees-Edwards shear imposes, u_x = shear rate (y - y_mid) with y_mid the
// middle of the box in y (the convention of the DEM engine, engines/dem/Simulation.hpp, and of
// its whole-domain stress). Under shear the fluctuation velocity of Eq. 3.38 is taken about this
// profile at the particle's own position, not about a mean that is constant over a bin: a bin
// of width h would otherwise add the profile's variance gammadot^2 h^2 / 12 to <C_x^2>, i.e.
// gammadot^2 h^2 / 36 to T. In core: the engines' whole-domain stress and extract both use it.
#include "core/Types.hpp"
#include "core/data/Domain.hpp"

namespace grainbridge::core::data {

inline Vec3 streamingVelocity(const Domain& domain, const Vec3& position) {
  const double yMid = 0.5 * (domain.lo[1] + domain.hi[1]);
  return Vec3(domain.leesEdwardsShearRate * (position[1] - yMid), 0.0, 0.0);
}

}  // namespace grainbridge::core::data
