#include "engines/closures/OutOfRange.hpp"

#include <sstream>

#include "core/Error.hpp"

namespace grainbridge::closures {

void refuseValue(std::string_view law, std::string_view what, std::string_view expected, double value) {
  std::ostringstream msg;
  msg.precision(10);
  msg << law << ": " << what << " must be " << expected << ", got " << value;
  throw Error(msg.str());
}

}  // namespace grainbridge::closures
