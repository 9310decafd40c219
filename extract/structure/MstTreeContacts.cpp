#include "extract/structure/MstTreeContacts.hpp"

#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::structure {

std::vector<std::size_t> treeContactsUpToPass(const MultiPassMstResult& mst, int pass) {
  if (pass < 1 || static_cast<std::size_t>(pass) > mst.passes.size()) {
    throw Error("MST tree contacts: pass " + std::to_string(pass) + " is not in 1.." +
                std::to_string(mst.passes.size()));
  }
  std::vector<std::size_t> out;
  for (std::size_t p = 0; p < static_cast<std::size_t>(pass); ++p) {
    for (const MstEdge& edge : mst.passes[p].edges) {
      if (edge.treeContact && edge.previousSelections == 0) out.push_back(static_cast<std::size_t>(edge.contactIndex));
    }
  }
  return out;
}

}  // namespace grainbridge::extract::structure
