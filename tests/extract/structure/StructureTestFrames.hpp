#pragma once
// Hand-built particle frames for the force-network and MST tests: lattices with exact ties
// (dyadic spacings, so equal distances are bitwise equal), random dense packings, and contact
// lists filled on every array ParticleFrame::validate checks.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"
#include "extract/geometry/PairSearch.hpp"
#include "extract/geometry/PeriodicBox.hpp"

namespace grainbridge::extract::structure::testing {

using core::data::ParticleFrame;

inline void addParticle(ParticleFrame& f, std::int64_t id, const Vec3& position, double radius) {
  f.id.push_back(id);
  f.species.push_back(0);
  f.radius.push_back(radius);
  f.mass.push_back(1.0);
  f.position.push_back(position);
  f.velocity.push_back(Vec3::Zero());
  f.angularVelocity.push_back(Vec3::Zero());
}

// Contact between ids i and j with branch r_i - r_j and signed normal force fn (> 0 repulsive):
// forceNormal = fn * branch / |branch| is the force on i from j.
inline void addContact(ParticleFrame& f, std::int64_t i, std::int64_t j, const Vec3& branch, double fn) {
  auto& c = f.contacts;
  const Vec3 force = fn * branch.normalized();
  c.i.push_back(i);
  c.j.push_back(j);
  c.branch.push_back(branch);
  c.contactPoint.push_back(Vec3::Zero());
  c.forceNormal.push_back(force);
  c.forceTangential.push_back(Vec3::Zero());
  c.forceNormalElastic.push_back(force);
  c.forceNormalDissipative.push_back(Vec3::Zero());
  c.forceTangentialElastic.push_back(Vec3::Zero());
  c.forceTangentialDissipative.push_back(Vec3::Zero());
}

// Every overlapping pair (minimum image) becomes a contact with F_n = overlap, except that a
// contact is made tensile (F_n = -overlap) with probability tensileFraction. All pairs are
// checked directly up to 5000 particles (independent of the code under test); beyond that the
// candidate search finds them (timing frames only).
inline void addOverlapContacts(ParticleFrame& f, std::mt19937_64& rng, double tensileFraction = 0.0) {
  const geometry::PeriodicBox box(f.domain);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const auto consider = [&](std::size_t a, std::size_t b) {
    const Vec3 branch = box.minimumImage(f.position[a] - f.position[b]);
    const double overlap = f.radius[a] + f.radius[b] - branch.norm();
    if (overlap <= 0.0) return;
    const double sign = uniform(rng) < tensileFraction ? -1.0 : 1.0;
    addContact(f, f.id[a], f.id[b], branch, sign * overlap);
  };
  if (f.size() > 5000) {
    const double reach = 2.0 * *std::max_element(f.radius.begin(), f.radius.end());
    geometry::PairSearch(box, f.position, reach).forEachPair([&](std::size_t a, std::size_t b, double) {
      consider(a, b);
    });
    return;
  }
  for (std::size_t a = 0; a < f.size(); ++a) {
    for (std::size_t b = a + 1; b < f.size(); ++b) consider(a, b);
  }
}

// Ids that are not the array order: a shuffled, spaced-out set, so the (min id, max id)
// tie-break is exercised on ids rather than on indices.
inline std::vector<std::int64_t> shuffledIds(std::size_t n, std::mt19937_64& rng) {
  std::vector<std::int64_t> ids(n);
  for (std::size_t k = 0; k < n; ++k) ids[k] = 7 + 3 * static_cast<std::int64_t>(k);
  std::shuffle(ids.begin(), ids.end(), rng);
  return ids;
}

// Simple cubic lattice nx x ny x nz with spacing 0.9375 (exact in binary) and radius 0.5, so all
// nearest-neighbour distances are bitwise equal and in contact, all diagonals equal and not.
// jitterFraction of the sites are moved by up to 0.04 per axis, breaking some ties only.
inline ParticleFrame latticeFrame(int nx, int ny, int nz, bool periodic, double jitterFraction, std::uint64_t seed) {
  constexpr double spacing = 0.9375;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  ParticleFrame f;
  f.domain.lo = Vec3::Zero();
  f.domain.hi = Vec3(nx * spacing, ny * spacing, nz * spacing);
  f.domain.periodic = {periodic, periodic, periodic};
  const auto ids = shuffledIds(static_cast<std::size_t>(nx * ny * nz), rng);
  std::size_t k = 0;
  for (int x = 0; x < nx; ++x) {
    for (int y = 0; y < ny; ++y) {
      for (int z = 0; z < nz; ++z) {
        Vec3 p(x * spacing, y * spacing, z * spacing);
        if (uniform(rng) < jitterFraction) {
          p += 0.04 * Vec3(2 * uniform(rng) - 1, 2 * uniform(rng) - 1, 2 * uniform(rng) - 1);
        }
        addParticle(f, ids[k++], p, 0.5);
      }
    }
  }
  addOverlapContacts(f, rng);
  return f;
}

// n particles at uniformly random positions in a periodic cube at the given number density,
// radii in [0.5 - polydispersity, 0.5 + polydispersity], every overlapping pair a contact.
inline ParticleFrame randomFrame(std::size_t n, double numberDensity, double polydispersity, double tensileFraction,
                                 double leesEdwardsOffset, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double side = std::cbrt(static_cast<double>(n) / numberDensity);
  ParticleFrame f;
  f.domain.lo = Vec3(-1.0, 2.0, 0.5);
  f.domain.hi = f.domain.lo + Vec3(side, side, side);
  f.domain.periodic = {true, true, true};
  f.domain.leesEdwardsOffset = leesEdwardsOffset;
  const auto ids = shuffledIds(n, rng);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 p = f.domain.lo + side * Vec3(uniform(rng), uniform(rng), uniform(rng));
    addParticle(f, ids[k], p, 0.5 + polydispersity * (2 * uniform(rng) - 1));
  }
  addOverlapContacts(f, rng, tensileFraction);
  return f;
}

// Number density 1.15 / d^3 (solid fraction ~0.6 for d = 1): overlapping like a compressed
// random packing, one network percolating through the box.
inline ParticleFrame randomDenseFrame(std::size_t n, double polydispersity, double tensileFraction,
                                      double leesEdwardsOffset, std::uint64_t seed) {
  return randomFrame(n, 1.15, polydispersity, tensileFraction, leesEdwardsOffset, seed);
}

// Number density 0.3 / d^3: about one contact per particle, many separate networks (the BNP
// frame had 80).
inline ParticleFrame randomSparseFrame(std::size_t n, std::uint64_t seed) {
  return randomFrame(n, 0.3, 0.0, 0.0, 0.0, seed);
}

}  // namespace grainbridge::extract::structure::testing
