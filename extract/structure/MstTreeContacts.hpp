#pragma once
// The contacts a multi-pass MST has found by pass p: what Figs. 6.14-6.16 take the force PDF and
// force correlation of ("assigning the forces from the force networks to the corresponding edges
// in the MST"). Each distinct tree-contact edge counts once, in the pass that first selected it
// ("repeated edges are not counted", Section 6.3.3).
#include <cstddef>
#include <vector>

#include "extract/structure/MultiPassMst.hpp"

namespace grainbridge::extract::structure {

// Indices into frame.contacts of the tree-contact edges selected in passes 1..pass, in the order
// they were selected. Throws grainbridge::Error when pass is not in [1, mst.passes.size()].
std::vector<std::size_t> treeContactsUpToPass(const MultiPassMstResult& mst, int pass);

}  // namespace grainbridge::extract::structure
