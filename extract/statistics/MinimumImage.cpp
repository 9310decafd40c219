#include "extract/statistics/MinimumImage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::statistics {

MinimumImage::MinimumImage(const core::data::Domain& domain)
    : lo_(domain.lo), length_(domain.hi - domain.lo), periodic_(domain.periodic), offset_(domain.leesEdwardsOffset) {
  static const char* axisName[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    if (periodic_[static_cast<std::size_t>(a)] && !(length_[a] > 0.0)) {
      throw Error("minimum image: periodic axis " + std::string(axisName[a]) + " has box length " +
                  std::to_string(length_[a]) + " (domain hi must exceed lo)");
    }
  }
  const bool sheared = domain.leesEdwardsOffset != 0.0 || domain.leesEdwardsShearRate != 0.0;
  if (sheared && !(periodic_[0] && periodic_[1])) {
    throw Error("minimum image: Lees-Edwards offset/shear rate set on a box that is not periodic in x and y");
  }
}

Vec3 MinimumImage::separation(const Vec3& a, const Vec3& b) const {
  Vec3 d = a - b;
  // y first: crossing the gradient boundary displaces x by the Lees-Edwards offset.
  if (periodic_[1]) {
    const double n = std::round(d[1] / length_[1]);
    d[1] -= n * length_[1];
    d[0] -= n * offset_;
  }
  if (periodic_[0]) d[0] -= std::round(d[0] / length_[0]) * length_[0];
  if (periodic_[2]) d[2] -= std::round(d[2] / length_[2]) * length_[2];
  return d;
}

Vec3 MinimumImage::wrap(const Vec3& p) const {
  Vec3 q = p;
  if (periodic_[1]) {
    const double n = std::floor((q[1] - lo_[1]) / length_[1]);
    q[1] -= n * length_[1];
    q[0] -= n * offset_;
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

double MinimumImage::maxUniqueDistance() const {
  double r = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (periodic_[static_cast<std::size_t>(a)]) r = std::min(r, 0.5 * length_[a]);
  }
  return r;
}

}  // namespace grainbridge::extract::statistics
