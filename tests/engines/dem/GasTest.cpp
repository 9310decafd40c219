#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "engines/dem/Material.hpp"
#include "tests/engines/dem/DemTestSupport.hpp"

using namespace grainbridge;
using namespace grainbridge::dem;
using namespace grainbridge::dem::testing;

TEST(Explore, Gas) {
  PairMaterial m;
  m.kn = 2e5;
  const double meff = 0.5 * sphereMass(1, 1.91);
  const double tc = linearContactTime(m.kn, 0.0, meff);
  const double base = std::getenv("DIV") ? std::atof(std::getenv("DIV")) : 50.0;
  const int seed = std::getenv("SEED") ? std::atoi(std::getenv("SEED")) : 7;
  const double T0 = std::getenv("T0") ? std::atof(std::getenv("T0")) : 1.0;
  for (double div : {base, 2 * base}) {
    const double dt = tc / div;
    auto g = periodicGas(2000, 0.1, T0, m, dt, seed);
    Simulation sim(g.setup, g.particles);
    const double e0 = sim.energies().kinetic() + elasticEnergy(sim.frame(), m);
    const Vec3 p0 = sim.momentum();
    auto t0 = std::chrono::steady_clock::now();
    double sum = 0, maxErr = 0, sumsq = 0;
    int ns = 0;
    const long steps = static_cast<long>(100000 * div / base);
    const int every = static_cast<int>(div);
    double last = 0;
    for (long s = 1; s <= steps; ++s) {
      const bool rec = s % every == 0;
      sim.step(rec);
      if (rec) {
        const double pe = elasticEnergy(sim.frame(), m);
        const double e = sim.energies().kinetic() + pe;
        sum += (e - e0) / e0;
        sumsq += std::pow((e - e0) / e0, 2);
        ++ns;
        last = (e - e0) / e0;
        maxErr = std::max(maxErr, std::abs(e - e0) / e0);
      }
    }
    auto t1 = std::chrono::steady_clock::now();
    double pscale = 0;
    for (std::size_t i = 0; i < sim.particles().nOwned; ++i) pscale += sim.particles().mass[i] * sim.particles().v[i].norm();
    std::printf("seed %d div %g mean %.3e rms %.3e max %.3e final %.3e |dP|/sum m|v| %.2e time %.2f s\n", seed, div,
                sum / ns, std::sqrt(sumsq / ns), maxErr, last, (sim.momentum() - p0).norm() / pscale,
                std::chrono::duration<double>(t1 - t0).count());
  }
}
