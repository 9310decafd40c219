// The TF-DEM coupling force a_p + B_p (u_p - v_p) (issue 4) is evaluated every DEM step with
// the particle's current velocity: a sphere settling under gravity in a linear (Stokes-like)
// drag relaxes exponentially with time constant m/B to the terminal velocity u + m g / B
// (STYLE.md 9: terminal velocity under drag). And planar mode keeps a 2-D bed in its plane.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/engines/dem/DemTestSupport.hpp"

using namespace grainbridge;
using namespace grainbridge::dem;
using namespace grainbridge::dem::testing;

namespace {
// Largest deviation from the exact exponential relaxation over 10 relaxation times, relative to
// the terminal speed, and the final deviation from the terminal velocity.
std::pair<double, double> relax(double dt) {
  SimulationSetup s = openBox(table61Particle());
  s.gravity = Vec3(0, 0, -9.81);
  s.dt = dt;
  s.fluidCoupled = true;  // the coupling arrays act only in a fluid-coupled run
  Particles p;
  const double m = 2e-3;
  p.addOwned(0, 0, 0.5, m, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), false);
  const double beta = 0.05;       // B_p [kg/s]: relaxation time m/B = 0.04 s
  const Vec3 gas(0.3, 0.0, 0.1);  // u_p
  p.couplingB[0] = beta;
  p.couplingU[0] = gas;
  p.couplingA[0] = Vec3(0.0, 1e-3, 0.0);  // a_p, e.g. a pressure-gradient force
  Simulation sim(s, std::move(p));
  const double tau = m / beta;
  const Vec3 terminal = gas + (m * s.gravity + Vec3(0.0, 1e-3, 0.0)) / beta;
  double worst = 0.0;
  const auto steps = static_cast<int>(std::lround(10.0 * tau / dt));
  for (int k = 1; k <= steps; ++k) {
    sim.step();
    const Vec3 exact = terminal * (1.0 - std::exp(-sim.time() / tau));  // v(0) = 0
    worst = std::max(worst, (sim.particles().v[0] - exact).norm() / terminal.norm());
  }
  return {worst, (sim.particles().v[0] - terminal).norm() / terminal.norm()};
}
}  // namespace

TEST(Coupling, LinearDragRelaxesToTerminalVelocity) {
  const auto [coarse, coarseFinal] = relax(1e-4);  // dt = tau/400
  const auto [fine, fineFinal] = relax(5e-5);
  // The drag uses the velocity at the middle of the step (velocity Verlet), so the transient
  // converges at first order in dt/tau: halving dt halves the error. The terminal velocity
  // u + (m g + a) / B is reached exactly.
  EXPECT_LT(coarse, 1e-3);
  EXPECT_NEAR(coarse / fine, 2.0, 0.2);
  EXPECT_LT(coarseFinal, 1e-4);
  EXPECT_LT(fineFinal, 1e-4);
}

// The coupling arrays act only in a fluid-coupled run (TF-DEM): a plain DEM run falls freely
// whatever they hold, and the same run coupled feels them.
TEST(Coupling, ArraysActOnlyInAFluidCoupledRun) {
  auto fall = [](bool coupled) {
    SimulationSetup s = openBox(table61Particle());
    s.gravity = Vec3(0, 0, -9.81);
    s.dt = 1e-4;
    s.fluidCoupled = coupled;
    Particles p;
    p.addOwned(0, 0, 0.5, 2e-3, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), false);
    p.couplingA[0] = Vec3(0.0, 1e-3, 0.0);
    p.couplingB[0] = 0.05;
    p.couplingU[0] = Vec3(0.3, 0.0, 0.1);
    p.couplingPressure[0] = Vec3(2e-3, 0.0, 0.0);
    Simulation sim(s, std::move(p));
    for (int k = 0; k < 100; ++k) sim.step();
    return sim.particles().v[0];
  };
  const Vec3 plain = fall(false);
  EXPECT_EQ(plain.x(), 0.0);
  EXPECT_EQ(plain.y(), 0.0);
  EXPECT_NEAR(plain.z(), -9.81 * 100 * 1e-4, 1e-12);
  const Vec3 coupled = fall(true);
  EXPECT_GT(coupled.x(), 1e-3);  // pushed by the pressure force and dragged towards u
  EXPECT_GT(coupled.y(), 1e-3);  // a_p
}

// Body forces record what they applied (BodyForces.hpp): TF-DEM hands the gas exactly the
// coupling force the particles received, so the recorded parts must add up to the force the
// step integrated, bit for bit, and a frozen particle receives nothing.
TEST(BodyForces, RecordExactlyWhatTheParticlesReceived) {
  SimulationSetup s = openBox(table61Particle());
  s.gravity = Vec3(0.1, 0, -9.81);
  s.backgroundDamping = 1e-3;
  s.dt = 1e-4;
  s.fluidCoupled = true;
  Particles p;
  p.addOwned(0, 0, 0.5, 2e-3, Vec3(1, 1, 1), Vec3(0.2, 0, 0), Vec3::Zero(), false);  // free: no contacts
  p.addOwned(1, 0, 0.5, 2e-3, Vec3(3, 3, 3), Vec3::Zero(), Vec3::Zero(), true);      // frozen
  for (std::size_t i = 0; i < 2; ++i) {
    p.couplingB[i] = 0.05;
    p.couplingU[i] = Vec3(0.3, 0.0, 0.1);
    p.couplingA[i] = Vec3(0.0, 1e-3, 0.0);
  }
  Simulation sim(s, std::move(p));
  sim.bodyForces().setRecording<Gravity>(true);
  sim.bodyForces().setRecording<BackgroundDamping>(true);
  sim.bodyForces().setRecording<FluidCoupling>(true);
  EXPECT_TRUE(sim.bodyForces().applied<Gravity>().empty());  // nothing recorded before a step
  for (int k = 0; k < 3; ++k) sim.step();
  const auto i = *sim.indexOf(0);
  const auto& q = sim.particles();
  const Vec3 g = sim.bodyForces().applied<Gravity>()[i];
  const Vec3 b = sim.bodyForces().applied<BackgroundDamping>()[i];
  const Vec3 c = sim.bodyForces().applied<FluidCoupling>()[i];
  // A frame's contact refresh after these unrecorded steps leaves the records (and forces) alone.
  sim.refreshContacts();
  EXPECT_EQ(sim.bodyForces().applied<FluidCoupling>()[i], c);
  EXPECT_EQ(sim.bodyForces().applied<BackgroundDamping>()[i], b);
  // The force of the last evaluation (the next half kick uses it) is the recorded sum, exactly.
  EXPECT_EQ(q.force[i], Vec3(Vec3::Zero() + g + b + c));
  // Each part is its law at the velocity of the evaluation (the half-step velocity).
  const Vec3 vHalf = q.v[i] - 0.5 * s.dt * q.invMass[i] * q.force[i];
  EXPECT_LE((g - q.mass[i] * s.gravity).norm(), 1e-15 * g.norm());
  EXPECT_LE((b + s.backgroundDamping * vHalf).norm(), 1e-12 * b.norm());
  EXPECT_LE((c - (q.couplingA[i] + q.couplingB[i] * (q.couplingU[i] - vHalf))).norm(), 1e-12 * c.norm());
  const auto frozen = *sim.indexOf(1);
  EXPECT_EQ(sim.bodyForces().applied<FluidCoupling>()[frozen], Vec3::Zero());
  EXPECT_EQ(q.force[frozen], Vec3::Zero());
  // Recording changes nothing in the trajectory.
  SimulationSetup s2 = s;
  Particles p2;
  p2.addOwned(0, 0, 0.5, 2e-3, Vec3(1, 1, 1), Vec3(0.2, 0, 0), Vec3::Zero(), false);
  p2.couplingB[0] = 0.05;
  p2.couplingU[0] = Vec3(0.3, 0.0, 0.1);
  p2.couplingA[0] = Vec3(0.0, 1e-3, 0.0);
  Simulation plain(s2, std::move(p2));
  for (int k = 0; k < 3; ++k) plain.step();
  EXPECT_EQ(plain.particles().v[0], q.v[i]);
}

TEST(Planar, BedStaysInItsPlaneAndSpinsAboutItsNormal) {
  SimulationSetup s = openBox(table61Particle());
  s.gravity = Vec3(0, 0, -1);
  s.planarAxis = 1;  // motion in x-z
  s.walls.push_back(floorWall(table61Wall()));
  Particles p;
  for (int i = 0; i < 20; ++i) {
    p.addOwned(i, 0, 0.5, 1.0, Vec3(1.05 * i - 10.0, 0.0, 0.6 + 0.3 * (i % 3)), Vec3(0.2 * (i % 5) - 0.4, 0.7, 0.0),
               Vec3(0.3, 0.2, 0.1), false);
  }
  Simulation sim(s, std::move(p));
  std::size_t contacts = 0;
  for (int k = 0; k < 20000; ++k) {
    sim.step();
    contacts = std::max(contacts, sim.contactCount());
  }
  for (std::size_t i = 0; i < sim.particles().nOwned; ++i) {
    EXPECT_EQ(sim.particles().x[i][1], 0.0);
    EXPECT_EQ(sim.particles().v[i][1], 0.0);
    EXPECT_EQ(sim.particles().omega[i][0], 0.0);
    EXPECT_EQ(sim.particles().omega[i][2], 0.0);
  }
  EXPECT_GT(contacts, 0u);  // the layer did interact
}
