#include "extract/structure/ContactEdges.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "core/Error.hpp"

namespace grainbridge::extract::structure {

std::vector<ContactEdge> listContactEdges(const core::data::ParticleFrame& frame, const ParticleIdIndex& index) {
  const auto& contacts = frame.contacts;
  std::vector<ContactEdge> edges(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    ContactEdge& e = edges[k];
    e.rankI = index.requireRank(contacts.i[k], "contact", k);
    e.rankJ = index.requireRank(contacts.j[k], "contact", k);
    e.contactIndex = k;
    if (e.rankI == e.rankJ) {
      throw Error("contact " + std::to_string(k) + " joins particle id " + std::to_string(contacts.i[k]) +
                  " to itself; a contact needs two different particles");
    }
    const double length = contacts.branch[k].norm();
    if (!(length > 0.0)) {
      throw Error("contact " + std::to_string(k) + " between particle ids " + std::to_string(contacts.i[k]) + " and " +
                  std::to_string(contacts.j[k]) + " has a zero or non-finite branch vector, so its normal force " +
                  "has no direction");
    }
    e.normalForce = contacts.forceNormal[k].dot(contacts.branch[k]) / length;
  }

  // A pair listed twice would be counted twice in coordination and could enter a tree twice.
  std::vector<std::pair<std::size_t, std::size_t>> pairs(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    pairs[k] = std::minmax(edges[k].rankI, edges[k].rankJ);
  }
  std::sort(pairs.begin(), pairs.end());
  const auto repeated = std::adjacent_find(pairs.begin(), pairs.end());
  if (repeated != pairs.end()) {
    throw Error("the contact list holds the particle pair (" + std::to_string(index.idAtRank(repeated->first)) + ", " +
                std::to_string(index.idAtRank(repeated->second)) + ") more than once; each pair must appear once");
  }
  return edges;
}

}  // namespace grainbridge::extract::structure
