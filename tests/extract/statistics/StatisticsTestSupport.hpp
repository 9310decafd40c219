#pragma once
// Samplers and frame builders for the extract/statistics tests. Every expected value in those
// tests follows from these constructions (known densities, independent or analytically
// correlated fields), never from a previous run of the code under test.
#include <cmath>
#include <random>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::statistics::testing {

// Samples of the normalised density proportional to (1 - b e^{-(f - alpha)^2}) e^{-beta f} on
// f >= 0 (the shape of Eq. 6.13; Eq. 6.11 for alpha = 0), by rejection: propose f ~ Exp(beta)
// and accept with probability 1 - b e^{-(f - alpha)^2}, which is in [0, 1] for 0 <= b <= 1.
inline std::vector<double> sampleForceShape(double b, double beta, double alpha, std::size_t n, std::mt19937_64& rng) {
  std::exponential_distribution<double> proposal(beta);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> out;
  out.reserve(n);
  while (out.size() < n) {
    const double f = proposal(rng);
    if (u(rng) < 1.0 - b * std::exp(-(f - alpha) * (f - alpha))) out.push_back(f);
  }
  return out;
}

// A frame whose contacts carry the given signed normal forces (F_n > 0 repulsive) at the given
// contact points, with random branch directions of length d.
inline core::data::ParticleFrame frameWithContacts(const std::vector<Vec3>& points, const std::vector<double>& fn,
                                                   std::mt19937_64& rng, double d = 1.0) {
  core::data::ParticleFrame f;
  f.step = 1200;
  std::normal_distribution<double> g(0.0, 1.0);
  auto& c = f.contacts;
  for (std::size_t k = 0; k < points.size(); ++k) {
    Vec3 n(g(rng), g(rng), g(rng));
    n.normalize();
    c.i.push_back(static_cast<std::int64_t>(2 * k));
    c.j.push_back(static_cast<std::int64_t>(2 * k + 1));
    c.branch.push_back(d * n);
    c.contactPoint.push_back(points[k]);
    c.forceNormal.push_back(fn[k] * n);
    c.forceTangential.push_back(Vec3::Zero());
    c.forceNormalElastic.push_back(fn[k] * n);
    c.forceNormalDissipative.push_back(Vec3::Zero());
    c.forceTangentialElastic.push_back(Vec3::Zero());
    c.forceTangentialDissipative.push_back(Vec3::Zero());
  }
  return f;
}

inline core::data::Domain periodicBox(const Vec3& lo, const Vec3& hi) {
  core::data::Domain d;
  d.lo = lo;
  d.hi = hi;
  d.periodic = {true, true, true};
  return d;
}

}  // namespace grainbridge::extract::statistics::testing
