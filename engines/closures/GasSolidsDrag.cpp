#include "engines/closures/GasSolidsDrag.hpp"

#include "core/Error.hpp"

namespace grainbridge::closures {

void throwUnknownDragLaw(std::string_view name, const std::vector<std::string>& known) {
  std::string list;
  for (const auto& n : known) list += (list.empty() ? "" : ", ") + n;
  throw Error("unknown gas-solids drag law \"" + std::string(name) + "\" (known: " + list + ")");
}

}  // namespace grainbridge::closures
