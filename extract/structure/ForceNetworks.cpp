#include "extract/structure/ForceNetworks.hpp"

#include <algorithm>
#include <limits>
#include <tuple>

#include "extract/structure/ContactEdges.hpp"
#include "extract/structure/DisjointSets.hpp"
#include "extract/structure/ParticleIdIndex.hpp"

namespace grainbridge::extract::structure {

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// Components with >= 2 particles of the subgraph made of `selected` edges: per component its
// particle and edge counts. Returns the component label of every rank (kNone for a singleton).
std::vector<std::size_t> labelComponents(std::size_t particleCount, const std::vector<ContactEdge>& edges,
                                         const std::vector<char>& selected, std::vector<ComponentSize>& sizes) {
  DisjointSets sets(particleCount);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (selected[k]) sets.unite(edges[k].rankI, edges[k].rankJ);
  }
  std::vector<std::size_t> labelOfRoot(particleCount, kNone);
  std::vector<std::size_t> label(particleCount, kNone);
  sizes.clear();
  // Ascending rank, so components are numbered by their smallest member id.
  for (std::size_t r = 0; r < particleCount; ++r) {
    const std::size_t root = sets.find(r);
    if (sets.sizeOfSet(root) < 2) continue;
    if (labelOfRoot[root] == kNone) {
      labelOfRoot[root] = sizes.size();
      sizes.push_back({sets.sizeOfSet(root), 0});
    }
    label[r] = labelOfRoot[root];
  }
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (selected[k]) ++sizes[label[edges[k].rankI]].contacts;
  }
  return label;
}

}  // namespace

ForceNetworkAnalysis analyzeForceNetworks(const core::data::ParticleFrame& frame, const ForceNetworkOptions& options) {
  frame.validate();
  const ParticleIdIndex index(frame.id);
  const std::vector<ContactEdge> edges = listContactEdges(frame, index);
  const std::size_t n = index.size();

  ForceNetworkAnalysis result;
  std::vector<char> repulsive(edges.size(), 0);
  double forceSum = 0.0;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    repulsive[k] = edges[k].repulsive() ? 1 : 0;
    if (repulsive[k]) {
      ++result.repulsiveContacts;
      forceSum += edges[k].normalForce;
    }
  }
  result.excludedContacts = edges.size() - result.repulsiveContacts;
  if (result.repulsiveContacts > 0) result.meanNormalForce = forceSum / static_cast<double>(result.repulsiveContacts);

  // Strong contacts: F_n strictly above the mean over all repulsive contacts (Fig. 6.11).
  std::vector<char> strong(edges.size(), 0);
  std::vector<char> touchesStrong(n, 0);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (!repulsive[k] || !(edges[k].normalForce > result.meanNormalForce)) continue;
    strong[k] = 1;
    ++result.strongContacts;
    touchesStrong[edges[k].rankI] = touchesStrong[edges[k].rankJ] = 1;
  }
  result.strongParticles = static_cast<std::size_t>(std::count(touchesStrong.begin(), touchesStrong.end(), 1));
  std::vector<ComponentSize> strongSizes;
  labelComponents(n, edges, strong, strongSizes);
  result.strongComponents = strongSizes.size();
  for (const ComponentSize& s : strongSizes) {
    if (std::tie(s.particles, s.contacts) >
        std::tie(result.largestStrongComponent.particles, result.largestStrongComponent.contacts)) {
      result.largestStrongComponent = s;
    }
  }

  std::vector<ComponentSize> sizes;
  const std::vector<std::size_t> label = labelComponents(n, edges, repulsive, sizes);
  result.networks.resize(sizes.size());
  // Members in ascending rank = ascending id; memberIndex is a rank's position in its network.
  std::vector<std::size_t> memberIndex(n, kNone);
  for (std::size_t r = 0; r < n; ++r) {
    if (label[r] == kNone) continue;
    ForceNetwork& net = result.networks[label[r]];
    memberIndex[r] = net.particleIds.size();
    net.particleIds.push_back(index.idAtRank(r));
    if (touchesStrong[r]) ++net.strongParticles;
  }
  std::vector<std::vector<ExtentEdge>> extentEdges(sizes.size());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (!repulsive[k]) continue;
    const ContactEdge& e = edges[k];
    ForceNetwork& net = result.networks[label[e.rankI]];
    ++net.contacts;
    if (strong[k]) ++net.strongContacts;
    extentEdges[label[e.rankI]].push_back({memberIndex[e.rankI], memberIndex[e.rankJ], frame.contacts.branch[k]});
  }
  for (std::size_t c = 0; c < sizes.size(); ++c) {
    ForceNetwork& net = result.networks[c];
    net.coordination = 2.0 * static_cast<double>(net.contacts) / static_cast<double>(net.particles());
    net.extent = measureNetworkExtent(net.particles(), extentEdges[c], options.gravity);
    result.particlesInNetworks += net.particles();
  }
  // Labels were assigned by smallest member id, so a stable sort keeps that as the last key.
  std::stable_sort(result.networks.begin(), result.networks.end(), [](const ForceNetwork& a, const ForceNetwork& b) {
    return std::make_tuple(a.particles(), a.contacts) > std::make_tuple(b.particles(), b.contacts);
  });
  return result;
}

}  // namespace grainbridge::extract::structure
