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
  for (double div : {50.0, 100.0, 200.0}) {
    const double dt = tc / div;
    auto g = periodicGas(2000, 0.1, 1.0, m, dt, 7);
    Simulation sim(g.setup, g.particles);
    const double e0 = sim.energies().kinetic() + elasticEnergy(sim.frame(), m);
    auto t0 = std::chrono::steady_clock::now();
    double sum = 0, sumC = 0, maxErr = 0;
    int ns = 0;
    const int steps = static_cast<int>(20000 * div / 50);
    const int every = static_cast<int>(div);
    for (int s = 1; s <= steps; ++s) {
      const bool rec = s % every == 0;
      sim.step(rec);
      if (rec) {
        const double pe = elasticEnergy(sim.frame(), m);
        const double e = sim.energies().kinetic() + pe;
        const double ec = e - pe * m.kn * dt * dt / (4 * meff);
        sum += (e - e0) / e0;
        sumC += (ec - e0) / e0;
        ++ns;
        maxErr = std::max(maxErr, std::abs(e - e0) / e0);
        if (s % (every * 40) == 0)
          std::printf("div %g step %d err %.3e corr %.3e pe %.3e max %.3e\n", div, s, (e - e0) / e0, (ec - e0) / e0,
                      pe / e0, maxErr);
      }
    }
    auto t1 = std::chrono::steady_clock::now();
    std::printf("div %g mean err %.3e mean corrected %.3e max %.3e time %.2f s\n", div, sum / ns, sumC / ns, maxErr,
                std::chrono::duration<double>(t1 - t0).count());
  }
}
