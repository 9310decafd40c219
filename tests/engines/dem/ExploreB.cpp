#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "engines/dem/Material.hpp"
#include "tests/engines/dem/DemTestSupport.hpp"

using namespace grainbridge;
using namespace grainbridge::dem;
using namespace grainbridge::dem::testing;

TEST(Explore, Binary) {
  PairMaterial m;
  m.kn = 2e5;
  const double mass = sphereMass(1, 1.91);
  const double meff = 0.5 * mass;
  const double tc = linearContactTime(m.kn, 0.0, meff);
  for (double div : {50.0, 100.0, 200.0}) {
    const double dt = tc / div;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (double b : {0.0, 0.5, 0.9, 0.99, 0.999}) {
    double s1 = 0, s2 = 0;
    const int n = 100;
    for (int k = 0; k < n; ++k) {
      const double speed = 1.0;
      SimulationSetup setup = openBox(m, 1, dt);
      Particles p;
      const double gap = 0.01 + speed * dt * u(rng);
      p.addOwned(0, 0, 0.5, mass, Vec3(-0.5 - gap / 2, 0, 0), Vec3(speed / 2, 0, 0), Vec3::Zero(), false);
      p.addOwned(1, 0, 0.5, mass, Vec3(std::sqrt(1 - b * b) * 0 + 0.5 + gap / 2, b, 0), Vec3(-speed / 2, 0, 0),
                 Vec3::Zero(), false);
      // place 1 so that at contact the offset is b: start far along x
      Simulation sim(setup, p);
      const double e0 = sim.energies().kinetic();
      int inContact = 0;
      for (int s = 0; s < 100000; ++s) {
        sim.step();
        if (sim.contactCount() > 0) inContact = 1;
        if (inContact && sim.contactCount() == 0) break;
      }
      const double err = (sim.energies().kinetic() - e0) / e0;
      s1 += err;
      s2 += err * err;
    }
    std::printf("div %g b %g mean %.3e rms %.3e\n", div, b, s1 / n, std::sqrt(s2 / n));
    }
  }
}
