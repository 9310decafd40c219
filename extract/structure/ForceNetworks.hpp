#pragma once
// Force networks of one particle frame (Section 6.3.2): "a collection of particles such that
// every particle in the force network is in contact with at least one other particle, and each
// particle has a nonzero normal contact force". Here: the connected components, with at least two
// particles, of the graph whose edges are the particle-particle contacts with repulsive normal
// force F_n > 0 (ContactEdges.hpp; VALIDATION.md). Reference values (BNP, T = 10, mu_wall = 0.5):
// 80 networks, the largest 5796 particles with network-averaged coordination 3.98 and a strong
// subnetwork of 3375 particles.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"
#include "extract/structure/NetworkExtent.hpp"

namespace grainbridge::extract::structure {

struct ForceNetworkOptions {
  // Direction of gravity for NetworkExtent::gravityExtent; zero leaves it 0. Frames do not store
  // gravity, so the caller passes the engine's.
  Vec3 gravity = Vec3::Zero();
};

struct ForceNetwork {
  std::vector<std::int64_t> particleIds;  // members, ascending id
  std::size_t contacts = 0;               // repulsive contacts between members
  // Network-averaged coordination number 2 contacts / particles (Section 6.3.2, 3.98 for the
  // largest BNP network): each contact counts for both of its particles.
  double coordination = 0.0;
  // The strong subnetwork inside this network: contacts with F_n above the frame's mean F_n (the
  // Fig. 6.11 threshold) and the members touching at least one of them (3375 of 5796 in the text).
  std::size_t strongContacts = 0;
  std::size_t strongParticles = 0;
  NetworkExtent extent;

  [[nodiscard]] std::size_t particles() const { return particleIds.size(); }
};

struct ComponentSize {
  std::size_t particles = 0;
  std::size_t contacts = 0;
};

struct ForceNetworkAnalysis {
  std::size_t repulsiveContacts = 0;  // contacts with F_n > 0: the edges of every network
  std::size_t excludedContacts = 0;   // contacts with F_n <= 0 (dashpot-attractive or exactly zero)
  double meanNormalForce = 0.0;       // mean F_n over the repulsive contacts; 0 if there are none
  // Largest first: most particles, then most contacts, then the smallest member id.
  std::vector<ForceNetwork> networks;
  std::size_t particlesInNetworks = 0;
  // Frame-wide strong subnetwork: the contacts with F_n > meanNormalForce, the particles touching
  // them, and the connected components of that subgraph (with >= 2 particles).
  std::size_t strongContacts = 0;
  std::size_t strongParticles = 0;
  std::size_t strongComponents = 0;
  ComponentSize largestStrongComponent;  // most particles, then most contacts
};

// Throws grainbridge::Error for an inconsistent frame (ParticleFrame::validate) or contact list
// (listContactEdges).
ForceNetworkAnalysis analyzeForceNetworks(const core::data::ParticleFrame& frame,
                                          const ForceNetworkOptions& options = {});

}  // namespace grainbridge::extract::structure
