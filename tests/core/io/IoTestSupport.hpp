#pragma once
// Shared by the core/io tests: frames with every field filled by distinct, non-round
// values (so a round trip that swapped, dropped or truncated any array would show) and an
// error-message matcher.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <string>

#include "core/Error.hpp"
#include "core/data/FieldFrame.hpp"
#include "core/data/ParticleFrame.hpp"
#include "tests/support/Cli.hpp"

namespace grainbridge::iotest {

using grainbridge::testing::TempDir;  // tests/support/Cli.hpp

// Runs `f`, expecting a grainbridge::Error whose message contains every one of `parts`.
template <class F>
void expectError(F&& f, std::initializer_list<std::string> parts) {
  try {
    f();
    ADD_FAILURE() << "expected grainbridge::Error";
  } catch (const Error& e) {
    for (const auto& part : parts) EXPECT_THAT(e.what(), ::testing::HasSubstr(part));
  }
}

inline Vec3 v3(double x, double y, double z) { return {x, y, z}; }

// n particles on a line through a periodic box, m contacts between neighbours (the last
// one across the periodic x boundary), two walls and one wall contact per wall.
inline core::data::ParticleFrame sampleParticleFrame(std::int64_t step, double time, int n, int m,
                                                     bool withExternalForce = true) {
  core::data::ParticleFrame f;
  f.step = step;
  f.time = time;
  f.domain.lo = v3(0.0, -0.5, 0.0);
  f.domain.hi = v3(1.0, 0.5, 2.0);
  f.domain.periodic = {true, false, true};
  f.domain.leesEdwardsOffset = 0.0125;
  f.domain.leesEdwardsShearRate = 3.5;
  f.domain.walls.push_back({"plane", v3(0.0, -0.5, 0.0), v3(0.0, 1.0, 0.0), 0.0, v3(0.1, 0.0, 0.0)});
  f.domain.walls.push_back({"cylinder", v3(0.5, 0.0, 0.0), v3(0.0, 0.0, 1.0), 0.75, v3(0.0, 0.0, -0.2)});
  for (int p = 0; p < n; ++p) {
    const double s = p + 1.0;
    f.id.push_back(100 + 7 * p);
    f.species.push_back(p % 2);
    f.radius.push_back(0.01 + 0.001 * s);
    f.mass.push_back(2.5e-3 * s);
    f.position.push_back(v3((p + 0.5) / n, 0.01 * s, 1.0 + 0.1 * s));
    f.velocity.push_back(v3(0.1 * s, -0.2 * s, 0.3));
    f.angularVelocity.push_back(v3(1.0, 2.0 * s, -3.0));
    if (withExternalForce) f.externalForce.push_back(v3(0.0, 0.0, -9.81e-3 * s));
  }
  for (int c = 0; c < m; ++c) {
    const int a = c % n;
    const int b = (c + 1) % n;  // c = n-1 pairs the last particle with the first, across x
    const double s = c + 1.0;
    f.contacts.i.push_back(f.id[static_cast<std::size_t>(a)]);
    f.contacts.j.push_back(f.id[static_cast<std::size_t>(b)]);
    f.contacts.branch.push_back(v3(-1.0 / n, -0.01, -0.1));
    f.contacts.contactPoint.push_back(f.position[static_cast<std::size_t>(a)] + v3(0.5 / n, 0.005, 0.05));
    f.contacts.forceNormalElastic.push_back(v3(-2.0 * s, 0.1, 0.2));
    f.contacts.forceNormalDissipative.push_back(v3(-0.25 * s, 0.0, 0.01));
    f.contacts.forceTangentialElastic.push_back(v3(0.0, 0.5 * s, -0.1));
    f.contacts.forceTangentialDissipative.push_back(v3(0.0, 0.05, -0.01 * s));
    f.contacts.forceNormal.push_back(f.contacts.forceNormalElastic.back() + f.contacts.forceNormalDissipative.back());
    f.contacts.forceTangential.push_back(f.contacts.forceTangentialElastic.back() +
                                         f.contacts.forceTangentialDissipative.back());
  }
  if (n > 0) {
    for (std::int32_t w = 0; w < 2; ++w) {
      f.wallContacts.particle.push_back(f.id[0]);
      f.wallContacts.wall.push_back(w);
      f.wallContacts.point.push_back(v3(0.25, -0.5, 1.5 + w));
      f.wallContacts.forceNormal.push_back(v3(0.0, 4.5 + w, 0.0));
      f.wallContacts.forceTangential.push_back(v3(0.3, 0.0, -0.1 * w));
    }
  }
  return f;
}

// A 4 x 3 x 2 grid with two solids phases, named so that name order differs from phase
// order. Cell values encode (i, j, k) so an axis mix-up changes them.
inline core::data::FieldFrame sampleFieldFrame(std::int64_t step, double time) {
  core::data::FieldFrame f;
  f.step = step;
  f.time = time;
  f.grid.origin = v3(-0.1, 0.2, 0.3);
  f.grid.spacing = v3(0.05, 0.1, 0.2);
  f.grid.cells = {4, 3, 2};
  const auto& g = f.grid;
  const std::size_t cells = g.cellCount();
  f.ep_g.resize(cells);
  f.p_g.resize(cells);
  f.u_g.resize(cells);
  f.solids = {{"small", {}, {}, {}}, {"large", {}, {}, {}}};
  for (auto& s : f.solids) {
    s.ep_s.resize(cells);
    s.u_s.resize(cells);
    s.theta.resize(cells);
  }
  for (int k = 0; k < g.cells[2]; ++k) {
    for (int j = 0; j < g.cells[1]; ++j) {
      for (int i = 0; i < g.cells[0]; ++i) {
        const std::size_t c = g.index(i, j, k);
        const double code = i + 10.0 * j + 100.0 * k;
        f.ep_g[c] = 0.4 + 0.001 * code;
        f.p_g[c] = 101325.0 + code;
        f.u_g[c] = v3(i, j, k);
        for (std::size_t p = 0; p < f.solids.size(); ++p) {
          f.solids[p].ep_s[c] = (0.3 - 0.001 * code) / (p + 1.0);
          f.solids[p].u_s[c] = v3(-i, p, code);
          f.solids[p].theta[c] = 1e-4 * (code + 1.0) * (p + 1.0);
        }
      }
    }
  }
  return f;
}

}  // namespace grainbridge::iotest
