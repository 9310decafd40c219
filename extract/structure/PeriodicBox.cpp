#include "extract/structure/PeriodicBox.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::structure {

PeriodicBox::PeriodicBox(const core::data::Domain& domain)
    : periodic_(domain.periodic), lo_(domain.lo), length_(domain.hi - domain.lo), halfLength_(0.5 * length_) {
  static const char* const axisName[] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    if (periodic_[static_cast<std::size_t>(a)] && !(length_[a] > 0.0 && std::isfinite(length_[a]))) {
      throw Error(std::string("the domain is periodic in ") + axisName[a] +
                  " but its length hi - lo = " + std::to_string(length_[a]) + " is not positive");
    }
  }
  // The shear rate moves the offset in time but plays no part in one frame's geometry.
  leesEdwardsOffset_ = domain.leesEdwardsOffset;
  if (leesEdwardsOffset_ != 0.0 && !(periodic_[0] && periodic_[1])) {
    throw Error("the domain has a Lees-Edwards offset of " + std::to_string(leesEdwardsOffset_) +
                " but is not periodic in both x and y; Lees-Edwards images need both");
  }
}

}  // namespace grainbridge::extract::structure
