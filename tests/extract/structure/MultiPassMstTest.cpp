// Multi-pass MST (Section 6.3.3): exactness against brute-force Kruskal over all pairs, the
// spanning-forest and TCP properties VALIDATION.md lists, and the Fig. 6.13 example.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/Error.hpp"
#include "extract/geometry/PeriodicBox.hpp"
#include "extract/structure/ForceNetworks.hpp"
#include "extract/structure/MultiPassMst.hpp"
#include "tests/extract/structure/StructureTestFrames.hpp"
#include "tests/support/ValidationNote.hpp"
#include "tests/support/ValidationRecord.hpp"

namespace grainbridge::extract::structure {
namespace {

using core::data::ParticleFrame;
using testing::addContact;
using testing::addParticle;

using IdPair = std::pair<std::int64_t, std::int64_t>;
using ::grainbridge::testing::formatNote;
using ::grainbridge::testing::recordValidation;

constexpr const char* kSection = "Extraction (Section 2.3, Sections 6.3.2-6.3.3)";
constexpr const char* kReference = "Section 6.3.3; VALIDATION.md Extraction (multi-pass MST)";

// A case name as a validation-record id part: lower case, runs of other characters as one '_'.
std::string slug(const std::string& name) {
  std::string out;
  for (char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

// A union-find independent of the library's, keyed by id.
struct IdSets {
  std::map<std::int64_t, std::int64_t> parent;
  std::int64_t find(std::int64_t v) {
    if (!parent.count(v)) parent[v] = v;
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  }
  bool unite(std::int64_t a, std::int64_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent[a] = b;
    return true;
  }
};

// Partition of the vertices touched by `edges` into components (sets of ids).
std::set<std::set<std::int64_t>> componentsOf(const std::vector<IdPair>& edges) {
  IdSets sets;
  for (const auto& [a, b] : edges) sets.unite(a, b);
  std::map<std::int64_t, std::set<std::int64_t>> byRoot;
  for (const auto& [a, b] : edges) {
    byRoot[sets.find(a)].insert(a);
    byRoot[sets.find(b)].insert(b);
  }
  std::set<std::set<std::int64_t>> parts;
  for (auto& [root, members] : byRoot) parts.insert(members);
  return parts;
}

struct ReferenceEdge {
  std::int64_t idLow, idHigh;
  double length, weight;
  int previousSelections;
};

// Kruskal over ALL N(N-1)/2 pairs, every pass, weights |r_ij| factor^s (s capped at 1 for
// Once), ties on (w, min id, max id): the definition, with nothing left out.
std::vector<std::vector<ReferenceEdge>> bruteForceMultiPassMst(const ParticleFrame& f, int passes, double factor,
                                                               ElongationMode mode) {
  const geometry::PeriodicBox box(f.domain);
  struct Pair {
    std::int64_t low, high;
    double length;
    int s = 0;
  };
  std::vector<Pair> pairs;
  for (std::size_t a = 0; a < f.size(); ++a) {
    for (std::size_t b = a + 1; b < f.size(); ++b) {
      const bool aLow = f.id[a] < f.id[b];
      const std::size_t low = aLow ? a : b, high = aLow ? b : a;
      const double length = box.minimumImage(f.position[low] - f.position[high]).norm();
      pairs.push_back({f.id[low], f.id[high], length});
    }
  }
  std::vector<std::vector<ReferenceEdge>> result;
  for (int pass = 1; pass <= passes; ++pass) {
    std::vector<std::tuple<double, std::int64_t, std::int64_t, std::size_t>> order;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const int exponent = mode == ElongationMode::Compounding ? pairs[k].s : std::min(pairs[k].s, 1);
      order.emplace_back(pairs[k].length * std::pow(factor, static_cast<double>(exponent)), pairs[k].low, pairs[k].high,
                         k);
    }
    std::sort(order.begin(), order.end());
    IdSets sets;
    std::vector<ReferenceEdge> tree;
    std::vector<std::size_t> chosen;
    for (const auto& [w, low, high, k] : order) {
      if (!sets.unite(low, high)) continue;
      tree.push_back({low, high, pairs[k].length, w, pairs[k].s});
      chosen.push_back(k);
    }
    for (std::size_t k : chosen) ++pairs[k].s;
    result.push_back(tree);
  }
  return result;
}

std::vector<IdPair> contactEdgesUpTo(const MultiPassMstResult& r, int pass) {
  std::vector<IdPair> edges;
  for (int p = 0; p < pass; ++p) {
    for (const MstEdge& e : r.passes[static_cast<std::size_t>(p)].edges) {
      if (e.treeContact && e.previousSelections == 0) edges.emplace_back(e.idLow, e.idHigh);
    }
  }
  return edges;
}

struct BruteForceCase {
  const char* name;
  ParticleFrame frame;
};

std::vector<BruteForceCase> bruteForceCases() {
  std::vector<BruteForceCase> cases;
  cases.push_back({"open lattice, all ties", testing::latticeFrame(7, 7, 6, false, 0.0, 1)});
  cases.push_back({"periodic lattice, 30% jittered", testing::latticeFrame(7, 7, 6, true, 0.3, 2)});
  cases.push_back({"random dense, polydisperse", testing::randomDenseFrame(300, 0.05, 0.1, 0.0, 3)});
  cases.push_back({"random dense, Lees-Edwards", testing::randomDenseFrame(300, 0.0, 0.0, 1.7, 4)});
  return cases;
}

// (a) Every pass equals brute-force Kruskal over all pairs: exactly, edge by edge and in order,
// when the cutoff covers every pair; on the edges of weight <= cutoff (and on every contact
// edge) with the default cutoff.
TEST(MultiPassMst, EveryPassEqualsBruteForceKruskalOverAllPairs) {
  for (const BruteForceCase& c : bruteForceCases()) {
    for (const ElongationMode mode : {ElongationMode::Compounding, ElongationMode::Once}) {
      SCOPED_TRACE(std::string(c.name) + (mode == ElongationMode::Once ? ", once" : ", compounding"));
      MultiPassMstOptions options;
      options.elongation = mode;
      const auto reference = bruteForceMultiPassMst(c.frame, options.passes, options.elongationFactor, mode);

      MultiPassMstOptions everyPair = options;
      everyPair.candidateCutoff = 100.0;  // beyond every box diagonal here
      const MultiPassMstResult all = runMultiPassMst(c.frame, everyPair);
      ASSERT_EQ(all.candidateEdges, c.frame.size() * (c.frame.size() - 1) / 2);
      ASSERT_EQ(all.forestTrees, 1u);

      const MultiPassMstResult local = runMultiPassMst(c.frame, options);
      ASSERT_LT(local.candidateEdges, all.candidateEdges);
      std::size_t referenceEdges = 0;  // over all passes, for the validation record
      std::size_t matchingEdges = 0;   // equal to brute force in ids, weight, selections and order
      bool passed = true;
      for (std::size_t p = 0; p < reference.size(); ++p) {
        SCOPED_TRACE("pass " + std::to_string(p + 1));
        const auto& want = reference[p];
        const auto& got = all.passes[p].edges;
        referenceEdges += want.size();
        for (std::size_t k = 0; k < std::min(got.size(), want.size()); ++k) {
          const bool same = got[k].idLow == want[k].idLow && got[k].idHigh == want[k].idHigh &&
                            got[k].weight == want[k].weight && got[k].previousSelections == want[k].previousSelections;
          matchingEdges += same ? 1 : 0;
          passed = passed && same;
        }
        passed = passed && got.size() == want.size();
        ASSERT_EQ(got.size(), want.size());
        for (std::size_t k = 0; k < want.size(); ++k) {
          ASSERT_EQ(std::make_pair(got[k].idLow, got[k].idHigh), std::make_pair(want[k].idLow, want[k].idHigh));
          ASSERT_EQ(got[k].weight, want[k].weight);
          ASSERT_EQ(got[k].previousSelections, want[k].previousSelections);
        }

        std::vector<IdPair> wantBelow, gotBelow;
        for (const auto& e : want) {
          if (e.weight <= local.candidateCutoff) wantBelow.emplace_back(e.idLow, e.idHigh);
        }
        for (const auto& e : local.passes[p].edges) {
          if (e.withinCutoff) gotBelow.emplace_back(e.idLow, e.idHigh);
        }
        EXPECT_EQ(gotBelow, wantBelow);
        passed = passed && gotBelow == wantBelow;
        std::set<IdPair> wantSet;
        for (const auto& e : want) wantSet.emplace(e.idLow, e.idHigh);
        for (const auto& e : local.passes[p].edges) {
          if (e.contactIndex >= 0) {
            EXPECT_TRUE(wantSet.count({e.idLow, e.idHigh}));
            passed = passed && wantSet.count({e.idLow, e.idHigh}) == 1;
          }
        }
      }
      const char* modeName = mode == ElongationMode::Once ? "once" : "compounding";
      recordValidation(
          {formatNote("extract.mst.brute_force.%s.%s", slug(c.name).c_str(), modeName), kSection,
           formatNote("multi-pass MST (%s elongation by 1.2) on '%s' (%zu particles): edges of passes 1-%zu equal to "
                      "brute-force Kruskal over all pairs",
                      modeName, c.name, c.frame.size(), reference.size()),
           kReference, static_cast<double>(referenceEdges), static_cast<double>(matchingEdges),
           "exact (every edge, weight and order)", passed,
           formatNote("every pair as a candidate (%zu edges): edge by edge; default cutoff %.4f (%zu candidate "
                      "edges): the edges of weight <= cutoff and every contact edge",
                      all.candidateEdges, local.candidateCutoff, local.candidateEdges)});
    }
  }
}

// (b) Footnote 6: an MST on N_P particles has N_P - 1 edges; so has every tree of pass 1's
// spanning forest and every pass-1 TCP.
TEST(MultiPassMst, PassOneGivesParticlesMinusOneEdgesPerTree) {
  const ParticleFrame f = testing::randomSparseFrame(300, 5);
  MultiPassMstOptions options;
  options.passes = 1;
  options.candidateCutoff = 1.5;  // small enough that the forest has several trees
  const MultiPassMstResult r = runMultiPassMst(f, options);
  const MstPass& first = r.passes.front();
  ASSERT_GT(r.forestTrees, 1u);
  EXPECT_EQ(first.edges.size() + r.forestTrees, f.size());

  std::vector<IdPair> forestEdges, contactEdges;
  for (const MstEdge& e : first.edges) {
    forestEdges.emplace_back(e.idLow, e.idHigh);
    if (e.treeContact) contactEdges.emplace_back(e.idLow, e.idHigh);
  }
  for (const auto* edges : {&forestEdges, &contactEdges}) {
    const auto parts = componentsOf(*edges);
    std::size_t vertices = 0;
    for (const auto& part : parts) vertices += part.size();
    EXPECT_EQ(edges->size(), vertices - parts.size());  // sum over trees of (N_P - 1)
  }
  std::size_t tcpParticles = 0, tcpEdges = 0;
  for (const TreeSize& t : first.trees) {
    EXPECT_EQ(t.edges, t.particles - 1);
    tcpParticles += t.particles;
    tcpEdges += t.edges;
  }
  EXPECT_EQ(first.largestTree.edges, first.largestTree.particles - 1);
  EXPECT_EQ(first.otherTrees + 1, first.trees.size());
  EXPECT_EQ(first.largestTree.edges + first.otherTreeEdges, tcpEdges);
  EXPECT_EQ(tcpEdges, contactEdges.size());
  EXPECT_EQ(tcpParticles - first.trees.size(), tcpEdges);
  bool passed = first.edges.size() + r.forestTrees == f.size() &&
                first.largestTree.edges == first.largestTree.particles - 1 && tcpEdges == contactEdges.size() &&
                tcpParticles - first.trees.size() == tcpEdges;
  for (const auto* edges : {&forestEdges, &contactEdges}) {
    const auto parts = componentsOf(*edges);
    std::size_t vertices = 0;
    for (const auto& part : parts) vertices += part.size();
    passed = passed && edges->size() == vertices - parts.size();
  }
  for (const TreeSize& t : first.trees) passed = passed && t.edges == t.particles - 1;
  recordValidation({"extract.mst.pass1_edges_per_tree", kSection,
                    "pass 1 of the multi-pass MST gives N_P - 1 edges per tree: edges of the spanning forest against "
                    "particles minus trees (and so for every tree of contacting particles)",
                    "Section 6.3.3 footnote 6", static_cast<double>(f.size() - r.forestTrees),
                    static_cast<double>(first.edges.size()), "exact", passed,
                    formatNote("300-particle sparse frame, candidate cutoff 1.5: %zu trees in the forest, %zu trees of "
                               "contacting particles with %zu edges",
                               r.forestTrees, first.trees.size(), tcpEdges)});
}

// (c) Section 6.3.3: on monodisperse frames pass 1's TCPs have the vertex sets of the contact
// graph's components (every contact is shorter than d, every non-contact at least d, so Kruskal
// has joined each contact component before it takes any non-contact edge), and the Table 6.2
// pass-1 numbers N_P, N_T and the TCP size distribution equal those of the force networks.
TEST(MultiPassMst, PassOneTreesOfContactingParticlesAreTheContactComponents) {
  struct Case {
    const char* name;
    ParticleFrame frame;
  };
  std::vector<Case> cases;
  cases.push_back({"random monodisperse", testing::randomDenseFrame(400, 0.0, 0.0, 0.0, 6)});
  cases.push_back({"random monodisperse, Lees-Edwards", testing::randomDenseFrame(400, 0.0, 0.0, 2.3, 7)});
  cases.push_back({"jittered lattice", testing::latticeFrame(7, 7, 6, true, 0.5, 8)});
  cases.push_back({"sparse monodisperse", testing::randomSparseFrame(400, 9)});

  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::vector<IdPair> contactGraph;
    for (std::size_t k = 0; k < c.frame.contacts.size(); ++k) {
      contactGraph.emplace_back(c.frame.contacts.i[k], c.frame.contacts.j[k]);
    }
    const MultiPassMstResult r = runMultiPassMst(c.frame);
    const auto tcps = componentsOf(contactEdgesUpTo(r, 1));
    const auto contactComponents = componentsOf(contactGraph);
    EXPECT_EQ(tcps, contactComponents);
    recordValidation({"extract.mst.pass1_contact_components." + slug(c.name), kSection,
                      std::string("pass 1's trees of contacting particles have the vertex sets of the contact-graph "
                                  "components, '") +
                          c.name + "': number of trees against number of components",
                      kReference, static_cast<double>(contactComponents.size()), static_cast<double>(tcps.size()),
                      "exact (equal vertex sets)", tcps == contactComponents,
                      formatNote("%zu particles, %zu contacts", c.frame.size(), c.frame.contacts.size())});

    const ForceNetworkAnalysis networks = analyzeForceNetworks(c.frame);
    const MstPass& first = r.passes.front();
    ASSERT_EQ(first.trees.size(), networks.networks.size());
    EXPECT_EQ(first.largestTree.particles, networks.networks.front().particles());
    EXPECT_EQ(first.otherTrees, networks.networks.size() - 1);
    for (std::size_t t = 0; t < first.trees.size(); ++t) {
      EXPECT_EQ(first.trees[t].particles, networks.networks[t].particles());
    }
    // A tree cannot tell a network that percolates through the periodic box (its unwrapping
    // depends on the spanning tree), so compare extents only for one that does not.
    const bool largestIsUnique = first.trees.size() < 2 || first.trees[0].particles > first.trees[1].particles;
    if (largestIsUnique && !networks.networks.front().extent.wrapsAroundBox) {
      EXPECT_NEAR(first.largestTreeExtent.largestCentreDistance, networks.networks.front().extent.largestCentreDistance,
                  1e-9);
    }
    if (std::string(c.name) == "sparse monodisperse") {
      EXPECT_GT(first.trees.size(), 5u);
    }
  }
}

// The same holds for the listed-contacts rule when some contacts are tensile: the rule decides
// which contacts form the graph, and the MST agrees with that graph.
TEST(MultiPassMst, ListedContactRuleKeepsTensileContacts) {
  const ParticleFrame f = testing::randomDenseFrame(400, 0.0, 0.3, 0.0, 11);
  std::vector<IdPair> listed;
  for (std::size_t k = 0; k < f.contacts.size(); ++k) listed.emplace_back(f.contacts.i[k], f.contacts.j[k]);
  MultiPassMstOptions options;
  options.contactRule = TreeContactRule::ListedContacts;
  const MultiPassMstResult r = runMultiPassMst(f, options);
  EXPECT_EQ(componentsOf(contactEdgesUpTo(r, 1)), componentsOf(listed));

  bool sawTensile = false;
  const MultiPassMstResult byDefault = runMultiPassMst(f);
  for (const MstEdge& e : byDefault.passes.front().edges) {
    if (e.contactIndex >= 0 && e.normalForce <= 0.0) {
      sawTensile = true;
      EXPECT_FALSE(e.treeContact) << "a tensile contact is not a force-network contact by default";
    }
  }
  EXPECT_TRUE(sawTensile);
}

// (d) Candidate edges beyond the automatic cutoff never change the reported structure: every
// edge of weight <= the smaller cutoff, every contact edge and every Table 6.2 number agree.
TEST(MultiPassMst, DoublingTheCutoffChangesNothing) {
  const char* names[] = {"random_dense_polydisperse", "periodic_lattice_30_jittered"};
  int frameIndex = 0;
  for (const ParticleFrame& f :
       {testing::randomDenseFrame(300, 0.05, 0.1, 0.0, 12), testing::latticeFrame(7, 7, 6, true, 0.3, 13)}) {
    const MultiPassMstResult base = runMultiPassMst(f);
    MultiPassMstOptions doubled;
    doubled.candidateCutoff = 2.0 * base.candidateCutoff;
    const MultiPassMstResult wide = runMultiPassMst(f, doubled);
    EXPECT_GT(wide.candidateEdges, base.candidateEdges);
    std::size_t passesDiffering = 0;
    for (std::size_t p = 0; p < base.passes.size(); ++p) {
      SCOPED_TRACE("pass " + std::to_string(p + 1));
      const MstPass &a = base.passes[p], &b = wide.passes[p];
      const auto project = [&](const MstPass& pass, bool contactsOnly) {
        std::vector<std::tuple<std::int64_t, std::int64_t, double, int, std::int64_t>> out;
        for (const MstEdge& e : pass.edges) {
          const bool keep = contactsOnly ? e.contactIndex >= 0 : e.weight <= base.candidateCutoff;
          if (keep) out.emplace_back(e.idLow, e.idHigh, e.weight, e.previousSelections, e.contactIndex);
        }
        return out;
      };
      EXPECT_EQ(project(a, false), project(b, false));
      EXPECT_EQ(project(a, true), project(b, true));
      EXPECT_EQ(a.largestTree.particles, b.largestTree.particles);
      EXPECT_EQ(a.largestTree.edges, b.largestTree.edges);
      EXPECT_EQ(a.otherTrees, b.otherTrees);
      EXPECT_EQ(a.otherTreeEdges, b.otherTreeEdges);
      EXPECT_EQ(a.newContactEdges, b.newContactEdges);
      EXPECT_EQ(a.largestTreeExtent.largestCentreDistance, b.largestTreeExtent.largestCentreDistance);
      const bool same = project(a, false) == project(b, false) && project(a, true) == project(b, true) &&
                        a.largestTree.particles == b.largestTree.particles &&
                        a.largestTree.edges == b.largestTree.edges && a.otherTrees == b.otherTrees &&
                        a.otherTreeEdges == b.otherTreeEdges && a.newContactEdges == b.newContactEdges &&
                        a.largestTreeExtent.largestCentreDistance == b.largestTreeExtent.largestCentreDistance;
      passesDiffering += same ? 0 : 1;
    }
    recordValidation({formatNote("extract.mst.double_cutoff.%s", names[frameIndex]), kSection,
                      formatNote("doubling the candidate cutoff changes nothing (%s, %zu particles): passes whose "
                                 "edges below the cutoff, contact edges or Table 6.2 numbers differ",
                                 names[frameIndex], f.size()),
                      kReference, 0.0, static_cast<double>(passesDiffering), "exact",
                      passesDiffering == 0 && wide.candidateEdges > base.candidateEdges,
                      formatNote("cutoff %.4f (%zu candidate edges) against %.4f (%zu)", base.candidateCutoff,
                                 base.candidateEdges, wide.candidateCutoff, wide.candidateEdges)});
    ++frameIndex;
  }
}

// (e) Fig. 6.13: particles 1, 2, 3 all in contact with each other, E(1,3) the longest of their
// three edges (less compressed); 4 and 5 in contact with each other only; 3 nearest to 4 but not
// touching it. Pass 1: MST {E(1,2), E(2,3), E(3,4), E(4,5)}; deleting the non-contact E(3,4)
// leaves the TCPs {1,2,3} (2 edges) and {4,5} (1 edge). Pass 2, with the pass-1 edges elongated
// by 1.2, selects E(1,3): all three contacts of {1,2,3} are captured.
TEST(MultiPassMst, FigureSixThirteenFiveParticleExample) {
  ParticleFrame f;
  const double d = 1.0;
  const Vec3 p1(0, 0, 0), p2(0.97, 0, 0);
  // 3 at distance 0.99 from 1 and 0.96 from 2.
  const double x3 = (0.99 * 0.99 - 0.96 * 0.96 + 0.97 * 0.97) / (2 * 0.97);
  const Vec3 p3(x3, std::sqrt(0.99 * 0.99 - x3 * x3), 0);
  const Vec3 p4 = p3 + Vec3(0, 1.05, 0);    // not touching 3
  const Vec3 p5 = p4 + Vec3(0.6, 0.78, 0);  // |p5 - p4| = 0.984
  const std::vector<Vec3> pos{p1, p2, p3, p4, p5};
  for (std::int64_t id = 1; id <= 5; ++id) addParticle(f, id, pos[static_cast<std::size_t>(id - 1)], d / 2);
  const auto dist = [&](int a, int b) {
    return (pos[static_cast<std::size_t>(a - 1)] - pos[static_cast<std::size_t>(b - 1)]).norm();
  };
  // The geometry the text describes.
  ASSERT_GT(dist(1, 3), dist(1, 2));
  ASSERT_GT(dist(1, 3), dist(2, 3));
  ASSERT_LT(dist(1, 3), 1.2 * dist(2, 3));
  for (auto [a, b] : {std::pair{1, 2}, {1, 3}, {2, 3}, {4, 5}}) ASSERT_LT(dist(a, b), d);
  for (auto [a, b] : {std::pair{1, 4}, {1, 5}, {2, 4}, {2, 5}, {3, 4}, {3, 5}}) ASSERT_GT(dist(a, b), d);
  for (auto [a, b] : {std::pair{1, 4}, {1, 5}, {2, 4}, {2, 5}, {3, 5}}) ASSERT_GT(dist(a, b), dist(3, 4));
  for (auto [a, b] : {std::pair{1, 2}, {1, 3}, {2, 3}, {4, 5}}) {
    addContact(f, a, b, pos[static_cast<std::size_t>(a - 1)] - pos[static_cast<std::size_t>(b - 1)], d - dist(a, b));
  }

  MultiPassMstOptions options;
  options.passes = 2;
  const MultiPassMstResult r = runMultiPassMst(f, options);
  const auto idsOf = [](const MstPass& p, bool contactsOnly) {
    std::set<IdPair> out;
    for (const MstEdge& e : p.edges) {
      if (!contactsOnly || e.treeContact) out.emplace(e.idLow, e.idHigh);
    }
    return out;
  };
  const MstPass& first = r.passes[0];
  EXPECT_EQ(idsOf(first, false), (std::set<IdPair>{{1, 2}, {2, 3}, {3, 4}, {4, 5}}));
  EXPECT_EQ(idsOf(first, true), (std::set<IdPair>{{1, 2}, {2, 3}, {4, 5}}));
  EXPECT_EQ(first.largestTree.particles, 3u);
  EXPECT_EQ(first.largestTree.edges, 2u);
  EXPECT_EQ(first.otherTrees, 1u);
  EXPECT_EQ(first.otherTreeEdges, 1u);
  EXPECT_EQ(componentsOf(contactEdgesUpTo(r, 1)), (std::set<std::set<std::int64_t>>{{1, 2, 3}, {4, 5}}));
  recordValidation(
      {"extract.mst.fig6_13.pass1", kSection,
       "Fig. 6.13 five-particle example, pass 1: trees of contacting particles {1,2,3} (2 edges) and {4,5} (1 edge) "
       "after the non-contact E(3,4) is deleted; number of such trees",
       "Section 6.3.3, Fig. 6.13", 2.0, static_cast<double>(first.trees.size()), "exact (the trees described)",
       idsOf(first, false) == std::set<IdPair>{{1, 2}, {2, 3}, {3, 4}, {4, 5}} &&
           idsOf(first, true) == std::set<IdPair>{{1, 2}, {2, 3}, {4, 5}} && first.largestTree.particles == 3u &&
           first.largestTree.edges == 2u && first.otherTrees == 1u && first.otherTreeEdges == 1u &&
           componentsOf(contactEdgesUpTo(r, 1)) == std::set<std::set<std::int64_t>>{{1, 2, 3}, {4, 5}},
       "MST {E(1,2), E(2,3), E(3,4), E(4,5)}"});

  const MstPass& second = r.passes[1];
  EXPECT_TRUE(idsOf(second, true).count({1, 3}));
  EXPECT_EQ(second.newContactEdges, 1u);
  EXPECT_EQ(second.largestTree.particles, 3u);
  EXPECT_EQ(second.largestTree.edges, 3u);  // all contacts among 1, 2, 3
  EXPECT_EQ(second.otherTrees, 1u);
  EXPECT_EQ(second.otherTreeEdges, 1u);
  // Pass 2 weights: E(1,3) 0.99 (new), E(2,3) 1.2 x 0.96, E(1,2) 1.2 x 0.97 (now the longest
  // of the three, dropped), E(4,5) and E(3,4) elongated.
  EXPECT_EQ(idsOf(second, false), (std::set<IdPair>{{1, 3}, {2, 3}, {3, 4}, {4, 5}}));
  bool weightsPassed = true;
  for (const MstEdge& e : second.edges) {
    if (e.idLow == 2 && e.idHigh == 3) {
      EXPECT_DOUBLE_EQ(e.weight, 1.2 * dist(2, 3));
      EXPECT_EQ(e.previousSelections, 1);
      // EXPECT_DOUBLE_EQ's "within 4 ulps": almost equal both ways.
      weightsPassed = weightsPassed && ::testing::DoubleLE("", "", e.weight, 1.2 * dist(2, 3)) &&
                      ::testing::DoubleLE("", "", 1.2 * dist(2, 3), e.weight) && e.previousSelections == 1;
    }
  }
  recordValidation(
      {"extract.mst.fig6_13.pass2", kSection,
       "Fig. 6.13 five-particle example, pass 2 (pass-1 edges elongated by 1.2) selects E(1,3): edges of the tree of "
       "contacting particles {1,2,3} (all three of its contacts captured)",
       "Section 6.3.3, Fig. 6.13", 3.0, static_cast<double>(second.largestTree.edges), "exact (the trees described)",
       weightsPassed && idsOf(second, true).count({1, 3}) == 1 && second.newContactEdges == 1u &&
           second.largestTree.particles == 3u && second.largestTree.edges == 3u && second.otherTrees == 1u &&
           second.otherTreeEdges == 1u && idsOf(second, false) == std::set<IdPair>{{1, 3}, {2, 3}, {3, 4}, {4, 5}},
       "pass-2 MST {E(1,3), E(2,3), E(3,4), E(4,5)}; one new contact edge"});
}

// Compounding and once-only elongation differ exactly where an edge was selected twice:
// triangle P-Q 1.0, P-R 0.5, Q-R 1.3. Passes 1 and 2 take P-Q; in pass 3 it weighs 1.44
// (compounding, so Q-R at 1.3 wins) or 1.2 (once, so P-Q stays).
TEST(MultiPassMst, ElongationModesDifferOnlyAfterTwoSelections) {
  ParticleFrame f;
  const double x = -0.22;
  addParticle(f, 10, Vec3(0, 0, 0), 0.1);                        // P
  addParticle(f, 20, Vec3(1, 0, 0), 0.1);                        // Q
  addParticle(f, 30, Vec3(x, std::sqrt(0.25 - x * x), 0), 0.1);  // R
  MultiPassMstOptions options;
  options.passes = 3;
  options.candidateCutoff = 3.0;
  const auto passThree = [&](ElongationMode mode) {
    options.elongation = mode;
    const MultiPassMstResult r = runMultiPassMst(f, options);
    std::set<IdPair> out;
    for (const MstEdge& e : r.passes[2].edges) out.emplace(e.idLow, e.idHigh);
    return out;
  };
  EXPECT_EQ(passThree(ElongationMode::Compounding), (std::set<IdPair>{{10, 30}, {20, 30}}));
  EXPECT_EQ(passThree(ElongationMode::Once), (std::set<IdPair>{{10, 20}, {10, 30}}));
}

TEST(MultiPassMst, EmptyAndContactlessFrames) {
  const MultiPassMstResult empty = runMultiPassMst(ParticleFrame{});
  ASSERT_EQ(empty.passes.size(), 5u);
  EXPECT_TRUE(empty.passes.front().edges.empty());
  EXPECT_EQ(empty.forestTrees, 0u);

  ParticleFrame apart;
  addParticle(apart, 1, Vec3(0, 0, 0), 0.5);
  addParticle(apart, 2, Vec3(1.5, 0, 0), 0.5);
  const MultiPassMstResult r = runMultiPassMst(apart);
  EXPECT_DOUBLE_EQ(r.candidateCutoff, 1.0 * std::pow(1.2, 5));
  ASSERT_EQ(r.passes.front().edges.size(), 1u);
  EXPECT_EQ(r.passes.front().edges.front().contactIndex, -1);
  EXPECT_TRUE(r.passes.front().trees.empty());
  EXPECT_EQ(r.passes.front().largestTree.particles, 0u);
}

TEST(MultiPassMst, RejectsBadOptionsWithTheirName) {
  const ParticleFrame f = testing::latticeFrame(3, 3, 3, false, 0.0, 14);
  const auto message = [&](MultiPassMstOptions o) {
    try {
      runMultiPassMst(f, o);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  MultiPassMstOptions o;
  o.passes = 0;
  EXPECT_NE(message(o).find("passes"), std::string::npos);
  o = {};
  o.elongationFactor = 0.9;
  EXPECT_NE(message(o).find("elongation factor"), std::string::npos);
  o = {};
  o.candidateCutoff = 0.95;  // below 0.9375 * 1.2^4
  EXPECT_NE(message(o).find("candidate cutoff"), std::string::npos);

  EXPECT_EQ(message({}), "no error");

  ParticleFrame twice = f;
  twice.id[1] = twice.id[0];
  EXPECT_THROW(runMultiPassMst(twice), Error);
}

}  // namespace
}  // namespace grainbridge::extract::structure
