#pragma once
// Multi-pass minimum spanning tree of Section 6.3.3 (Fig. 6.13, Table 6.2).
//
// Vertices are particles; an edge joins two particles with weight
//   w_p = |r_ij| * factor^s      (factor = 1.2 in the reference)
// in pass p, s being the number of earlier passes whose tree selected the edge ("the lengths of
// the edges selected in previous passes are elongated by a specified factor"). The reference does
// not say whether the elongation compounds; VALIDATION.md makes compounding the default and
// elongate-once (s capped at 1) an option. Ties break on (w, min id, max id), so the result is
// unique and does not depend on the order of the frame's arrays.
//
// Each pass is a minimum spanning forest (Kruskal) over the candidate edges: pairs with
// minimum-image centre distance |r_ij| <= cutoff. Why that is exact where it matters:
//   Kruskal on the complete graph decides an edge e by whether the edges before e in key order
//   (w, min id, max id) already join its ends. Every edge of weight <= cutoff has length <= cutoff
//   (factor >= 1), so it is a candidate; and so is every edge before it. Hence on the prefix of
//   edges with w <= cutoff, the candidate Kruskal and the complete-graph Kruskal see the same
//   edges in the same order and make the same decisions. Over several passes, by induction: an
//   edge's s can differ between the two computations only after a pass in which its weight
//   exceeded the cutoff in both, and since weights never decrease it stays above the cutoff in
//   both; so the edges of weight <= cutoff have the same weights, hence the same prefix and the
//   same decisions, in every pass. Every forest edge with w <= cutoff (flag `withinCutoff`) is
//   an edge of the complete-graph MST; an edge above it may not be (the complete graph might
//   join two candidate components more cheaply through a longer pair, or join them at all).
//   A contact edge has |r_ij| <= L (the largest contact distance) and s <= passes - 1
//   (compounding) or 1 (once), so its weight is at most L factor^(passes-1) in every pass: with
//   the default cutoff L factor^passes (VALIDATION.md; the extra factor is margin for round-off
//   between stored branch vectors and positions), every decision on every contact edge is exact,
//   and with it the trees of contacting particles and all of Table 6.2.
//
// Trees of contacting particles (TCPs, Section 6.3.3): delete the non-contact edges from the
// MST; what remains are the TCPs. After pass p the TCP graph is the union of the distinct
// contact edges selected in passes 1..p ("repeated edges are not counted"), and its connected
// components with >= 2 particles are the TCPs of Table 6.2 (for p >= 2 they may hold cycles).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"
#include "extract/structure/NetworkExtent.hpp"

namespace grainbridge::extract::structure {

enum class ElongationMode {
  Compounding,  // w = |r_ij| factor^s (default)
  Once,         // w = |r_ij| factor^min(s, 1)
};

// Which listed contacts count as contacts when MST edges are kept for the TCPs.
enum class TreeContactRule {
  // F_n > 0, the contacts of the force networks (ForceNetworks.hpp), so TCPs compare with them
  // directly (the last row of Table 6.2). Default.
  RepulsiveContacts,
  // Every pair in the contact list (geometric overlap), whatever the sign of F_n. On a
  // monodisperse frame every contact is shorter than every non-contact, so pass 1's TCPs are then
  // exactly the contact-graph components (Section 6.3.3). Under RepulsiveContacts that holds only
  // if no listed contact is tensile: a short tensile pair can take a tree's place and split a TCP.
  ListedContacts,
};

struct MultiPassMstOptions {
  int passes = 5;                 // Table 6.2 runs five; at most 100
  double elongationFactor = 1.2;  // Section 6.3.3; must be >= 1
  ElongationMode elongation = ElongationMode::Compounding;
  // Largest candidate edge length. 0 = automatic: L factor^passes with L the largest contact
  // distance |branch| (twice the largest radius if the frame has no contacts). An explicit value
  // below L factor^(passes-1) (compounding) or L factor (once) is refused: contact edges would no
  // longer be exact.
  double candidateCutoff = 0.0;
  TreeContactRule contactRule = TreeContactRule::RepulsiveContacts;
  Vec3 gravity = Vec3::Zero();  // for largestTreeExtent.gravityExtent; zero leaves it 0
};

struct MstEdge {
  std::int64_t idLow = 0, idHigh = 0;  // the two particles, idLow < idHigh
  double length = 0.0;                 // |r_ij|, minimum image
  double weight = 0.0;                 // |r_ij| factor^s as used in this pass
  int previousSelections = 0;          // s: earlier passes that selected this edge (0 = new now)
  bool withinCutoff = false;           // weight <= cutoff: provably an edge of the complete-graph MST
  std::int64_t contactIndex = -1;      // position in frame.contacts, -1 if the pair is not in contact
  double normalForce = 0.0;            // signed F_n of that contact (> 0 repulsive); 0 if none
  bool treeContact = false;            // kept in the TCPs under the contact rule
};

struct TreeSize {
  std::size_t particles = 0;  // N_P
  std::size_t edges = 0;      // N_E, distinct contact edges
};

struct MstPass {
  int pass = 0;  // 1-based
  // The minimum spanning forest of the candidate graph in this pass, in Kruskal (weight) order.
  // The force PDF and correlation of p-pass MST edges use the treeContact edges of passes 1..p
  // with previousSelections == 0 (each distinct edge once).
  std::vector<MstEdge> edges;
  // Table 6.2 columns. largestTree: the TCP with the most particles (then most edges, then the
  // smallest member id); otherTrees = N_T, otherTreeEdges = N_E summed over the rest.
  TreeSize largestTree;
  std::size_t otherTrees = 0;
  std::size_t otherTreeEdges = 0;
  std::vector<TreeSize> trees;      // every TCP, largest first (its distribution, Section 6.3.3)
  std::size_t newContactEdges = 0;  // distinct contact edges first selected in this pass
  // NetworkExtent.hpp on the largest TCP (52.2 d0 in the reference). A pass-1 TCP is a tree, so
  // it has no cycle that could reveal a wrap through a periodic box: wrapsAroundBox is only
  // meaningful from pass 2 on (ForceNetworks gives it for the full network).
  NetworkExtent largestTreeExtent;
};

struct MultiPassMstResult {
  double candidateCutoff = 0.0;         // the cutoff used
  double largestContactDistance = 0.0;  // L, max |branch| over the contact list
  std::size_t candidateEdges = 0;
  // Trees of each pass's spanning forest: the components of the candidate graph, singletons
  // included (the same in every pass, since the candidate edges are).
  std::size_t forestTrees = 0;
  std::vector<MstPass> passes;
};

// Throws grainbridge::Error for bad options (naming the option and the allowed range), an
// inconsistent frame or contact list, or a box the candidate search cannot handle.
MultiPassMstResult runMultiPassMst(const core::data::ParticleFrame& frame, const MultiPassMstOptions& options = {});

}  // namespace grainbridge::extract::structure
