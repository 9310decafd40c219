#include "engines/closures/GasSolidsDrag.hpp"

#include "core/Error.hpp"

namespace grainbridge::closures {

std::vector<std::string> GasSolidsDrag::names() { return {"syamlal_obrien", "ergun_wen_yu", "gidaspow"}; }

GasSolidsDrag GasSolidsDrag::byName(std::string_view name) {
  if (name == "syamlal_obrien") return {std::string(name), SyamlalOBrien{}};
  if (name == "ergun_wen_yu") return {std::string(name), ErgunWenYu::asPrinted()};
  if (name == "gidaspow") return {std::string(name), ErgunWenYu::gidaspow()};
  std::string known;
  for (const auto& n : names()) known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown gas-solids drag law \"" + std::string(name) + "\" (known: " + known + ")");
}

}  // namespace grainbridge::closures
