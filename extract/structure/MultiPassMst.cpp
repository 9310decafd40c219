#include "extract/structure/MultiPassMst.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include "core/Error.hpp"
#include "extract/geometry/PairSearch.hpp"
#include "extract/geometry/PeriodicBox.hpp"
#include "extract/structure/ContactEdges.hpp"
#include "extract/structure/DisjointSets.hpp"
#include "extract/structure/ParticleIdIndex.hpp"

namespace grainbridge::extract::structure {

namespace {

constexpr int kMaxPasses = 100;
constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

void checkOptions(const MultiPassMstOptions& o) {
  if (o.passes < 1 || o.passes > kMaxPasses) {
    throw Error("MST passes = " + std::to_string(o.passes) + " is out of range; use 1 to " +
                std::to_string(kMaxPasses) + " (Table 6.2 uses 5)");
  }
  if (!(o.elongationFactor >= 1.0) || !std::isfinite(o.elongationFactor)) {
    throw Error("MST elongation factor = " + std::to_string(o.elongationFactor) +
                " must be finite and >= 1 (Section 6.3.3 uses 1.2); a factor below 1 would shorten "
                "selected edges");
  }
  if (!(o.candidateCutoff >= 0.0) || !std::isfinite(o.candidateCutoff)) {
    throw Error("MST candidate cutoff = " + std::to_string(o.candidateCutoff) +
                " must be finite and >= 0 (0 chooses it automatically)");
  }
}

// Kruskal order: (weight, lower rank, higher rank); ranks follow ids, so this is (w, min id,
// max id) of VALIDATION.md.
bool before(double wa, std::uint32_t aLow, std::uint32_t aHigh, double wb, std::uint32_t bLow, std::uint32_t bHigh) {
  if (wa != wb) return wa < wb;
  if (aLow != bLow) return aLow < bLow;
  return aHigh < bHigh;
}

// A candidate edge: ranks a < b within the cutoff, 32-bit ranks to keep the (often tens of
// millions of) candidates at 16 bytes.
struct CandidatePair {
  double length = 0.0;  // |minimumImage(r_a - r_b)|, bitwise that of an all-pairs loop
  std::uint32_t a = 0, b = 0;
};

std::vector<CandidatePair> findCandidatePairs(const std::vector<Vec3>& positions, const core::data::Domain& domain,
                                              double cutoff) {
  if (positions.size() >= std::numeric_limits<std::uint32_t>::max()) {
    throw Error("the MST candidate search takes at most 2^32 - 1 particles; the frame has " +
                std::to_string(positions.size()));
  }
  const geometry::PairSearch search(geometry::PeriodicBox(domain), positions, cutoff);
  std::vector<CandidatePair> pairs;
  pairs.reserve(search.expectedPairCount());
  search.forEachPair([&](std::size_t a, std::size_t b, double length) {
    pairs.push_back({length, static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)});
  });
  return pairs;
}

struct ElongatedEdge {
  double weight = 0.0;
  std::uint32_t a = 0, b = 0;
  std::size_t candidate = 0;
};

// Candidate edges in (length, lower rank, higher rank) order, sorted lazily: a counting sort
// into length buckets (linear), then each bucket is sorted the first time Kruskal reaches it.
// Every pass stops once its forest is complete, well before the longest candidates in a dense
// packing (the cutoff is 1.2^passes contact lengths), so most buckets are never sorted. Edges
// that were selected keep their position: their bucket was sorted before they were reached.
class LengthOrderedEdges {
 public:
  LengthOrderedEdges(const std::vector<CandidatePair>& pairs, double cutoff) : edges_(pairs.size()) {
    const std::size_t buckets = std::max<std::size_t>(1, pairs.size() / 256);
    const double perLength = cutoff > 0.0 ? static_cast<double>(buckets) / cutoff : 0.0;
    const auto bucketOf = [&](const CandidatePair& p) {
      return std::min(buckets - 1, static_cast<std::size_t>(p.length * perLength));  // monotone in length
    };
    bucketEnd_.assign(buckets, 0);
    for (const CandidatePair& p : pairs) ++bucketEnd_[bucketOf(p)];
    std::size_t start = 0;
    std::vector<std::size_t> fill(buckets);
    for (std::size_t b = 0; b < buckets; ++b) {
      fill[b] = start;
      start += bucketEnd_[b];
      bucketEnd_[b] = start;
    }
    for (const CandidatePair& p : pairs) edges_[fill[bucketOf(p)]++] = p;
  }

  [[nodiscard]] std::size_t size() const { return edges_.size(); }
  // The k-th edge in key order; sorts its bucket if that has not been done yet.
  const CandidatePair& ordered(std::size_t k) {
    while (k >= sortedEnd_) {
      const auto first = edges_.begin() + static_cast<std::ptrdiff_t>(sortedEnd_);
      const auto last = edges_.begin() + static_cast<std::ptrdiff_t>(bucketEnd_[sortedBuckets_++]);
      std::sort(first, last, [](const CandidatePair& x, const CandidatePair& y) {
        return before(x.length, x.a, x.b, y.length, y.a, y.b);
      });
      sortedEnd_ = static_cast<std::size_t>(last - edges_.begin());
    }
    return edges_[k];
  }
  // An edge already reached through ordered().
  const CandidatePair& operator[](std::size_t k) const { return edges_[k]; }

 private:
  std::vector<CandidatePair> edges_;
  std::vector<std::size_t> bucketEnd_;
  std::size_t sortedBuckets_ = 0, sortedEnd_ = 0;
};

std::uint64_t pairKey(std::size_t low, std::size_t high, std::size_t n) {
  return static_cast<std::uint64_t>(low) * static_cast<std::uint64_t>(n) + static_cast<std::uint64_t>(high);
}

}  // namespace

MultiPassMstResult runMultiPassMst(const core::data::ParticleFrame& frame, const MultiPassMstOptions& options) {
  checkOptions(options);
  frame.validate();
  const ParticleIdIndex index(frame.id);
  const std::vector<ContactEdge> contacts = listContactEdges(frame, index);
  const std::size_t n = index.size();
  MultiPassMstResult result;

  // Candidate cutoff (see the header for why L factor^(passes-1) suffices for contact edges).
  for (const Vec3& branch : frame.contacts.branch) {
    result.largestContactDistance = std::max(result.largestContactDistance, branch.norm());
  }
  const double factor = options.elongationFactor;
  const int maxExponent =
      options.elongation == ElongationMode::Compounding ? options.passes - 1 : std::min(1, options.passes - 1);
  const double requiredCutoff = result.largestContactDistance * std::pow(factor, maxExponent);
  if (options.candidateCutoff > 0.0) {
    if (options.candidateCutoff < requiredCutoff) {
      throw Error("MST candidate cutoff = " + std::to_string(options.candidateCutoff) +
                  " is below the largest contact distance times the largest elongation, " +
                  std::to_string(requiredCutoff) + "; contact edges would not be exact. Raise it or use 0 (automatic)");
    }
    result.candidateCutoff = options.candidateCutoff;
  } else {
    double reach = result.largestContactDistance;
    if (contacts.empty()) {
      for (double r : frame.radius) reach = std::max(reach, 2.0 * r);  // the longest a contact could be
    }
    result.candidateCutoff = reach * std::pow(factor, options.passes);
  }
  const double cutoff = result.candidateCutoff;

  // Candidate edges on ranks (ascending id), ordered by length once: weights change only for the
  // edges already selected, which are merged in from a small list sorted per pass.
  std::vector<Vec3> positions(n);
  for (std::size_t r = 0; r < n; ++r) positions[r] = frame.position[index.frameIndexAtRank(r)];
  LengthOrderedEdges candidates(findCandidatePairs(positions, frame.domain, cutoff), cutoff);
  result.candidateEdges = candidates.size();

  std::unordered_map<std::uint64_t, std::size_t> contactOfPair;
  contactOfPair.reserve(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const auto [low, high] = std::minmax(contacts[k].rankI, contacts[k].rankJ);
    contactOfPair.emplace(pairKey(low, high, n), k);
  }

  std::vector<double> elongation(static_cast<std::size_t>(options.passes) + 1);
  for (std::size_t s = 0; s < elongation.size(); ++s) elongation[s] = std::pow(factor, static_cast<double>(s));
  const auto weightOf = [&](std::size_t candidate, std::uint8_t selections) {
    const std::size_t exponent =
        options.elongation == ElongationMode::Compounding ? selections : std::min<std::size_t>(selections, 1);
    return candidates[candidate].length * elongation[exponent];
  };

  std::vector<std::uint8_t> selections(candidates.size(), 0);  // s per candidate edge
  std::vector<std::size_t> elongatedCandidates;                // candidates with s >= 1
  DisjointSets forest(n), contactTrees(n);
  std::vector<std::size_t> treeContacts;  // distinct contact edges (into `contacts`) kept so far
  std::vector<std::size_t> labelOfRoot(n, kNone), memberIndex(n, kNone);

  for (int pass = 1; pass <= options.passes; ++pass) {
    std::vector<ElongatedEdge> elongated;
    elongated.reserve(elongatedCandidates.size());
    for (const std::size_t c : elongatedCandidates) {
      elongated.push_back({weightOf(c, selections[c]), candidates[c].a, candidates[c].b, c});
    }
    std::sort(elongated.begin(), elongated.end(), [](const ElongatedEdge& x, const ElongatedEdge& y) {
      return before(x.weight, x.a, x.b, y.weight, y.a, y.b);
    });

    // Kruskal over the merge of the two sorted streams. Every pass spans the same candidate
    // components, so after pass 1 it stops as soon as the forest is complete.
    forest.reset();
    std::vector<std::size_t> chosen;
    const std::size_t target = n == 0 ? 0 : (pass == 1 ? n - 1 : n - result.forestTrees);
    std::size_t nextPlain = 0, nextElongated = 0;
    while (chosen.size() < target) {
      while (nextPlain < candidates.size() && selections[nextPlain] > 0) ++nextPlain;
      const bool plainLeft = nextPlain < candidates.size(), elongatedLeft = nextElongated < elongated.size();
      if (!plainLeft && !elongatedLeft) break;
      bool takePlain = plainLeft;
      if (plainLeft && elongatedLeft) {
        const CandidatePair& p = candidates.ordered(nextPlain);
        const ElongatedEdge& e = elongated[nextElongated];
        takePlain = before(p.length, p.a, p.b, e.weight, e.a, e.b);
      }
      const std::size_t c = takePlain ? nextPlain++ : elongated[nextElongated++].candidate;
      const CandidatePair& edge = candidates.ordered(c);
      if (forest.unite(edge.a, edge.b)) chosen.push_back(c);
    }
    if (pass == 1) result.forestTrees = n - chosen.size();

    MstPass out;
    out.pass = pass;
    out.edges.reserve(chosen.size());
    for (const std::size_t c : chosen) {
      const CandidatePair& p = candidates[c];
      MstEdge edge;
      edge.idLow = index.idAtRank(p.a);
      edge.idHigh = index.idAtRank(p.b);
      edge.length = p.length;
      edge.weight = weightOf(c, selections[c]);
      edge.previousSelections = selections[c];
      edge.withinCutoff = edge.weight <= cutoff;
      const auto found = contactOfPair.find(pairKey(p.a, p.b, n));
      if (found != contactOfPair.end()) {
        const ContactEdge& contact = contacts[found->second];
        edge.contactIndex = static_cast<std::int64_t>(contact.contactIndex);
        edge.normalForce = contact.normalForce;
        edge.treeContact = options.contactRule == TreeContactRule::ListedContacts || contact.repulsive();
        if (edge.treeContact && selections[c] == 0) {
          contactTrees.unite(p.a, p.b);
          treeContacts.push_back(found->second);
          ++out.newContactEdges;
        }
      }
      out.edges.push_back(edge);
    }
    for (const std::size_t c : chosen) {
      if (selections[c] == 0) elongatedCandidates.push_back(c);
      if (selections[c] < std::numeric_limits<std::uint8_t>::max()) ++selections[c];
    }

    // Trees of contacting particles: components (>= 2 particles) of the kept contact edges,
    // labelled in ascending id of their smallest member.
    std::fill(labelOfRoot.begin(), labelOfRoot.end(), kNone);
    std::vector<TreeSize> sizes;
    std::vector<std::size_t> labelOfRank(n, kNone);
    for (std::size_t r = 0; r < n; ++r) {
      const std::size_t root = contactTrees.find(r);
      if (contactTrees.sizeOfSet(root) < 2) continue;
      if (labelOfRoot[root] == kNone) {
        labelOfRoot[root] = sizes.size();
        sizes.push_back({contactTrees.sizeOfSet(root), 0});
      }
      labelOfRank[r] = labelOfRoot[root];
    }
    for (const std::size_t k : treeContacts) ++sizes[labelOfRank[contacts[k].rankI]].edges;
    std::vector<std::size_t> order(sizes.size());
    for (std::size_t t = 0; t < order.size(); ++t) order[t] = t;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      if (sizes[x].particles != sizes[y].particles) return sizes[x].particles > sizes[y].particles;
      return sizes[x].edges > sizes[y].edges;
    });
    for (const std::size_t t : order) out.trees.push_back(sizes[t]);
    if (!order.empty()) {
      const std::size_t largest = order.front();
      out.largestTree = sizes[largest];
      out.otherTrees = sizes.size() - 1;
      for (const TreeSize& t : sizes) out.otherTreeEdges += t.edges;
      out.otherTreeEdges -= out.largestTree.edges;

      std::size_t members = 0;
      for (std::size_t r = 0; r < n; ++r) {
        if (labelOfRank[r] == largest) memberIndex[r] = members++;
      }
      std::vector<ExtentEdge> extentEdges;
      extentEdges.reserve(out.largestTree.edges);
      for (const std::size_t k : treeContacts) {
        const ContactEdge& contact = contacts[k];
        if (labelOfRank[contact.rankI] != largest) continue;
        extentEdges.push_back(
            {memberIndex[contact.rankI], memberIndex[contact.rankJ], frame.contacts.branch[contact.contactIndex]});
      }
      out.largestTreeExtent = measureNetworkExtent(members, extentEdges, options.gravity);
    }
    result.passes.push_back(std::move(out));
  }
  return result;
}

}  // namespace grainbridge::extract::structure
