#include "engines/closures/RadialDistribution.hpp"

#include <sstream>

#include "core/Error.hpp"

namespace grainbridge::closures {

double carnahanStarlingG0(double solidFraction) {
  // Written so that NaN fails the test too.
  if (!(solidFraction >= 0.0 && solidFraction < 1.0)) {
    std::ostringstream msg;
    msg.precision(10);
    msg << "radial distribution g0: solid fraction must be in [0, 1), got " << solidFraction;
    throw Error(msg.str());
  }
  const double voidFraction = 1.0 - solidFraction;
  return (1.0 - 0.5 * solidFraction) / (voidFraction * voidFraction * voidFraction);
}

}  // namespace grainbridge::closures
