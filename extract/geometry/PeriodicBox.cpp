#include "extract/geometry/PeriodicBox.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::geometry {

PeriodicBox::PeriodicBox(const core::data::Domain& domain)
    : periodic_(domain.periodic),
      lo_(domain.lo),
      length_(domain.hi - domain.lo),
      halfLength_(0.5 * length_),
      leesEdwardsOffset_(domain.leesEdwardsOffset) {
  static const char* const axisName[] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    if (periodic_[static_cast<std::size_t>(a)] && !(length_[a] > 0.0 && std::isfinite(length_[a]))) {
      throw Error(std::string("the domain is periodic in ") + axisName[a] +
                  " but its length hi - lo = " + std::to_string(length_[a]) + " is not positive and finite");
    }
  }
  // Only the offset enters one frame's geometry, but a shear rate on a box that cannot carry
  // Lees-Edwards images is an inconsistent domain all the same (the engine refuses to run one).
  const bool sheared = domain.leesEdwardsOffset != 0.0 || domain.leesEdwardsShearRate != 0.0;
  if (sheared && !(periodic_[0] && periodic_[1])) {
    throw Error("the domain has a Lees-Edwards offset of " + std::to_string(domain.leesEdwardsOffset) +
                " and shear rate of " + std::to_string(domain.leesEdwardsShearRate) +
                " but is not periodic in both x and y; Lees-Edwards images need both");
  }
}

Vec3 PeriodicBox::wrap(const Vec3& p) const {
  Vec3 q = p;
  // y first: moving a point down by whole boxes in y moves it back by the offset in x.
  if (periodic_[1]) {
    const double images = std::floor((q[1] - lo_[1]) / length_[1]);
    q[1] -= images * length_[1];
    q[0] -= images * leesEdwardsOffset_;
  }
  for (int a : {0, 2}) {
    if (periodic_[static_cast<std::size_t>(a)]) q[a] -= std::floor((q[a] - lo_[a]) / length_[a]) * length_[a];
  }
  // Round-off can leave q == hi; keep the half-open box exact for cell indexing.
  for (int a = 0; a < 3; ++a) {
    if (periodic_[static_cast<std::size_t>(a)] && q[a] >= lo_[a] + length_[a]) q[a] = lo_[a];
  }
  return q;
}

double PeriodicBox::maxUniqueDistance() const {
  double r = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (periodic_[static_cast<std::size_t>(a)]) r = std::min(r, halfLength_[a]);
  }
  return r;
}

}  // namespace grainbridge::extract::geometry
