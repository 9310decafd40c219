// Lees-Edwards simple shear (VALIDATION.md, DEM): in steady state the mean velocity profile is
// the imposed linear one, and the work done by the shear, -sigma_xy gammadot V (sigma of
// Eq. 2.3, positive in compression), equals the dissipation rate measured at the contacts.
// Frictionless spheres, e = 0.9, k* = k_n/(rho d^3 gammadot^2) = 1e5, dt = t_c/50.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include "engines/dem/Checkpoint.hpp"
#include "engines/dem/DomainStress.hpp"
#include "engines/dem/Insertion.hpp"
#include "engines/dem/LatticeInsertion.hpp"
#include "tests/engines/dem/DemTestSupport.hpp"
#include "tests/support/ValidationNote.hpp"
#include "tests/support/ValidationRecord.hpp"

using namespace grainbridge;
using namespace grainbridge::dem;
using namespace grainbridge::dem::testing;

namespace {

struct ShearRun {
  double slope;         // fitted d<u_x>/dy
  double intercept;     // <u_x> at the box centre
  double shearWork;     // time-averaged -sigma_xy gammadot V
  double dissipation;   // time-averaged dashpot dissipation rate
  double sigmaXyLower;  // sigma_xy from contacts in the lower and upper halves of the box
  double sigmaXyUpper;
};

ShearRun shear(int n, double phi, double strainsDiscarded, double strainsAveraged) {
  const double d = 1.0;
  const double rho = 6.0 / M_PI;  // m = 1
  const double gammadot = 1.0;
  const PairMaterial mat = frictionlessUnitMass(1e5 * rho * d * d * d * gammadot * gammadot, 0.9);  // k* = 1e5
  const double tc = linearContactTime(mat.kn, mat.gammaN, 0.5);
  const double box = std::cbrt(n * M_PI / 6.0 / phi);
  const SimulationSetup s = periodicCube(mat, box, tc / 50.0, gammadot);

  std::mt19937_64 rng(7);
  const auto centres = randomCentres(s, n, 0.5 * d, rng);
  // Fluctuations with zero mean: a net y momentum P_y would make the momentum about the
  // streaming profile drift as -gammadot P_y t (shear couples y motion into x).
  std::normal_distribution<double> noise(0.0, 0.3);
  std::vector<Vec3> fluct(static_cast<std::size_t>(n));
  Vec3 mean = Vec3::Zero();
  for (auto& c : fluct) {
    c = Vec3(noise(rng), noise(rng), noise(rng));
    mean += c / n;
  }
  Particles p;
  for (int i = 0; i < n; ++i) {
    const Vec3& x = centres[static_cast<std::size_t>(i)];
    const Vec3 v = Vec3(gammadot * (x[1] - 0.5 * box), 0, 0) + fluct[static_cast<std::size_t>(i)] - mean;
    p.addOwned(i, 0, 0.5 * d, 1.0, x, v, Vec3::Zero(), false);
  }
  Simulation sim(s, std::move(p));
  const auto discard = static_cast<std::int64_t>(strainsDiscarded / gammadot / s.dt);
  const auto average = static_cast<std::int64_t>(strainsAveraged / gammadot / s.dt);
  sim.run(discard);

  const int bins = 6;
  std::vector<double> sumU(bins, 0.0), count(bins, 0.0);
  double work = 0.0, dissipation = 0.0, lower = 0.0, upper = 0.0;
  int samples = 0;
  const double volume = box * box * box;
  for (std::int64_t k = 0; k < average; ++k) {
    const bool sample = k % 20 == 0;
    sim.step(sample);
    if (!sample) continue;
    const auto f = sim.frame();
    const Mat3 sigma = wholeDomainStress(f, volume);
    work += -sigma(0, 1) * gammadot * volume;
    dissipation += sim.dashpotDissipation();
    for (std::size_t c = 0; c < f.contacts.size(); ++c) {
      // contact part of sigma_xy attributed to the half of the box holding particle i
      const auto i = *sim.indexOf(f.contacts.i[c]);
      const double part = f.contacts.branch[c][0] * (f.contacts.forceNormal[c] + f.contacts.forceTangential[c])[1];
      (f.position[i][1] < 0.5 * box ? lower : upper) += part / (0.5 * volume);
    }
    for (std::size_t i = 0; i < f.size(); ++i) {
      const int b = std::min(bins - 1, static_cast<int>(f.position[i][1] / box * bins));
      sumU[static_cast<std::size_t>(b)] += f.velocity[i][0];
      count[static_cast<std::size_t>(b)] += 1.0;
    }
    ++samples;
  }
  // Least-squares line through the bin means.
  double sy = 0, su = 0, syy = 0, syu = 0;
  for (int b = 0; b < bins; ++b) {
    const double y = (b + 0.5) * box / bins - 0.5 * box;
    const double u = sumU[static_cast<std::size_t>(b)] / count[static_cast<std::size_t>(b)];
    sy += y;
    su += u;
    syy += y * y;
    syu += y * u;
  }
  const double slope = (bins * syu - sy * su) / (bins * syy - sy * sy);
  return {slope, su / bins, work / samples, dissipation / samples, lower / samples, upper / samples};
}

}  // namespace

TEST(LeesEdwards, SteadyShearHasLinearProfileAndShearWorkEqualsDissipation) {
  const auto r = shear(300, 0.2, 20.0, 60.0);
  RecordProperty("slope", std::to_string(r.slope));
  RecordProperty("shear_work", std::to_string(r.shearWork));
  RecordProperty("dissipation", std::to_string(r.dissipation));
  std::printf("slope %.5f intercept %.5f work %.6g dissipation %.6g (ratio %.4f) sigma_xy lower %.5g upper %.5g\n",
              r.slope, r.intercept, r.shearWork, r.dissipation, r.shearWork / r.dissipation, r.sigmaXyLower,
              r.sigmaXyUpper);
  EXPECT_NEAR(r.slope, 1.0, 0.02);
  EXPECT_NEAR(r.intercept, 0.0, 0.02 * 0.5 * std::cbrt(300 * M_PI / 6.0 / 0.2));
  EXPECT_GT(r.shearWork, 0.0);
  // sigma_xy is uniform: the halves on either side of the box centre (and so of the shearing
  // boundary, which joins the top half to the bottom one) agree.
  EXPECT_NEAR(r.sigmaXyLower / r.sigmaXyUpper, 1.0, 0.05);
  EXPECT_NEAR(r.shearWork / r.dissipation, 1.0, 0.02);
  using grainbridge::testing::formatNote;
  using grainbridge::testing::recordValidation;
  const char* section = "DEM (Chapter 6)";
  const std::string setup =
      "300 frictionless spheres, solid fraction 0.2, e = 0.9, k* = 1e5, dt = t_c/50, 20 strain units discarded, 60 "
      "averaged";
  const double halfBox = 0.5 * std::cbrt(300 * M_PI / 6.0 / 0.2);
  recordValidation({"dem.lees_edwards.velocity_profile", section,
                    "Lees-Edwards simple shear: slope of the steady mean-velocity profile over the imposed gammadot",
                    "VALIDATION.md DEM (Lees-Edwards simple shear)", 1.0, r.slope, "2 %",
                    std::abs(r.slope - 1.0) <= 0.02 && std::abs(r.intercept) <= 0.02 * halfBox,
                    formatNote("least-squares line through 6 bin means; intercept %.5f (within 2 %% of the half box "
                               "%.3f required); ",
                               r.intercept, halfBox) +
                        setup});
  recordValidation({"dem.lees_edwards.work_equals_dissipation", section,
                    "Lees-Edwards simple shear: work done by the shear, -sigma_xy gammadot V, against the dashpot "
                    "dissipation rate measured at the contacts",
                    "VALIDATION.md DEM (Lees-Edwards simple shear), Eq. 2.3", r.dissipation, r.shearWork, "2 %",
                    r.shearWork > 0.0 && std::abs(r.shearWork / r.dissipation - 1.0) <= 0.02, setup});
  recordValidation({"dem.lees_edwards.sigma_xy_uniform", section,
                    "Lees-Edwards simple shear: contact sigma_xy in the lower half of the box against the upper half "
                    "(uniform across the Lees-Edwards boundary)",
                    "VALIDATION.md DEM (Lees-Edwards simple shear)", r.sigmaXyUpper, r.sigmaXyLower, "5 %",
                    std::abs(r.sigmaXyLower / r.sigmaXyUpper - 1.0) <= 0.05, setup});
}

// A pair across the shearing boundary closes its list gap by both displacements plus the offset
// drift. Here each particle moves 0.149 (just under half the 0.3 skin) and the offset drifts
// 0.149 too, so a half-skin rule on each alone never rebuilds: the pair starts 0.015 beyond the
// list's reach and ends 0.088 inside contact. The rebuild must come in time for the contact.
TEST(LeesEdwards, RebuildCountsTheOffsetDriftWithBothDisplacements) {
  PairMaterial mat;
  mat.kn = 1e4;
  mat.kt = 0.0;
  mat.mu = 0.0;
  mat.gammaN = 0.0;
  const double travel = 0.149;  // per particle and for the offset, over t = 1
  // The offset drifts gammadot L_y t = travel.
  const SimulationSetup s = periodicCube(mat, 10.0, 1e-3, travel / 10.0);
  const double gap = 0.93;  // each component of the separation from A to B's upper image
  const Vec3 towardB = Vec3(-1.0, 1.0, 0.0).normalized();
  const Vec3 a(5.0, 9.6, 5.0);
  const Vec3 bImage = a + Vec3(-gap, gap, 0.0);  // |A B'| = 1.315 > 1 + skin: not listed
  const Vec3 b = bImage - Vec3(0.0, 10.0, 0.0);  // offset 0 at t = 0
  Particles p;
  p.addOwned(0, 0, 0.5, 1.0, a, travel * towardB, Vec3::Zero(), false);
  p.addOwned(1, 0, 0.5, 1.0, b, -travel * towardB, Vec3::Zero(), false);
  Simulation sim(s, std::move(p));

  bool touched = false;
  for (int k = 0; k < 1000; ++k) {
    sim.step();
    // Separation to B's image through the shearing boundary, as the ghost sees it.
    const auto& x = sim.particles().x;
    const std::size_t ia = *sim.indexOf(0), ib = *sim.indexOf(1);
    Vec3 r = x[ib] + Vec3(sim.shearOffset(sim.time()), 10.0, 0.0) - x[ia];
    r[0] -= 10.0 * std::round(r[0] / 10.0);
    if (r.norm() < 1.0) {
      touched = true;
      ASSERT_EQ(sim.contactCount(), 1u) << "centres " << r.norm() << " apart at step " << k + 1
                                        << " but the contact is not in the list";
    }
  }
  EXPECT_TRUE(touched);
  // The contact pushed them apart: A no longer moves straight toward B.
  EXPECT_LT(sim.particles().v[*sim.indexOf(0)].dot(towardB), travel);
}

// A sheared box resumed from its checkpoint file continues bit for bit: the file keeps the time
// of the last list build, which sets the Lees-Edwards offset its ghosts were built with.
TEST(LeesEdwards, ResumedFromItsCheckpointFileContinuesBitForBit) {
  PairMaterial mat;
  mat.kn = 1e5 * 6.0 / M_PI;
  mat.kt = 2.0 / 7.0 * mat.kn;
  mat.mu = 0.5;
  mat.gammaN = gammaForRestitution(0.9, mat.kn, 0.5);
  mat.gammaT = 0.5 * mat.gammaN;
  const int n = 200;
  const double box = std::cbrt(n * M_PI / 6.0 / 0.3);
  const SimulationSetup s = periodicCube(mat, box, linearContactTime(mat.kn, mat.gammaN, 0.5) / 50.0, 1.0);
  std::mt19937_64 rng(5);
  const auto centres = randomCentres(s, n, 0.5, rng);
  auto particles = [&] {
    Particles p;
    for (int i = 0; i < n; ++i) {
      const Vec3& x = centres[static_cast<std::size_t>(i)];
      p.addOwned(i, 0, 0.5, 1.0, x, Vec3(x[1] - 0.5 * box, 0, 0), Vec3::Zero(), false);
    }
    return p;
  };
  Simulation uninterrupted(s, particles());
  uninterrupted.run(20000);
  ASSERT_GT(uninterrupted.rebuilds(), 3);
  ASSERT_GT(s.shearRate * box * uninterrupted.time(), box);  // the offset has gone round
  const auto file = std::filesystem::temp_directory_path() / "grainbridge-lees-edwards-restart.ckpt";
  writeCheckpoint(file, uninterrupted.captureState(), "fingerprint");
  Simulation resumed(s, readCheckpoint(file, "fingerprint"));
  std::filesystem::remove(file);
  uninterrupted.run(5000);
  resumed.run(5000);
  ASSERT_EQ(resumed.particles().nOwned, uninterrupted.particles().nOwned);
  EXPECT_EQ(differingParticles(uninterrupted, resumed), 0u);
}

namespace {

// Touching pairs of the Lees-Edwards box [0, side]^3 at the offset `offset`, by brute force over
// nearest images (the image above is displaced by the offset along x).
std::size_t touchingPairsSheared(const Particles& p, double side, double offset) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    for (std::size_t j = i + 1; j < p.nOwned; ++j) {
      Vec3 r = p.x[j] - p.x[i];
      const double images = std::round(r[1] / side);
      r[1] -= images * side;
      r[0] -= images * offset;
      r[0] -= side * std::round(r[0] / side);
      r[2] -= side * std::round(r[2] / side);
      const double reach = p.radius[i] + p.radius[j];
      if (r.squaredNorm() < reach * reach) ++n;
    }
  }
  return n;
}

}  // namespace

// Two spheres streaming exactly with the profile (no peculiar motion) close their gap by the
// shear alone: the list must be rebuilt for the shear's distortion of the neighbourhood
// (rebuildReach's sigma_min), although neither moves relative to the streaming field. A 0.9
// apart in y and 1.5 behind in x: 1.75 apart, beyond the 1 + 0.3 skin the list holds; they touch
// after a strain of 1.18. Neither the offset drift nor the streaming motion forces a rebuild any
// more, so the list is rebuilt a few times, not every 15 steps as a rule on the whole
// displacement would (the offset alone drifts half the skin in 15 steps here).
TEST(LeesEdwards, ShearAloneClosesAGapAndTheListIsRebuiltForIt) {
  const PairMaterial mat = frictionlessUnitMass(1e4, 1.0);  // elastic (gamma_n = 0), no tangential spring
  const double side = 10.0;
  const SimulationSetup s = periodicCube(mat, side, 1e-3, 1.0);
  const Vec3 a(3.0, 5.45, 5.0);
  const Vec3 b(4.5, 4.55, 5.0);
  Simulation sim(s, shearedUnitSpheres(s, {a, b}));
  const std::int64_t startBuilds = sim.rebuilds();
  bool touched = false;
  for (int k = 0; k < 1300 && !touched; ++k) {
    sim.step();
    const auto& x = sim.particles().x;
    const double gap = (x[*sim.indexOf(1)] - x[*sim.indexOf(0)]).norm();
    if (gap < 1.0) {
      touched = true;
      EXPECT_EQ(sim.contactCount(), 1u) << "centres " << gap << " apart at step " << k + 1
                                        << " but the contact is not in the list";
      EXPECT_NEAR(sim.time(), (1.5 - std::sqrt(1.0 - 0.81)) / 0.9, 2e-3) << "they touch after a strain of 1.18";
    } else {
      ASSERT_EQ(sim.contactCount(), 0u) << "step " << k + 1;
    }
  }
  EXPECT_TRUE(touched);
  EXPECT_GE(sim.rebuilds() - startBuilds, 2) << "the shear's distortion alone must rebuild the list";
  EXPECT_LE(sim.rebuilds() - startBuilds, 5) << "the streaming motion and the offset drift should not rebuild it";
}

namespace {

// The cube of n unit spheres (d = m = 1) at solid fraction phi, periodic, frictionless with
// e = 0.9 and k* = k_n / (rho d^3 gammadot^2) = 1e5 at unit rate, dt = t_c / 50, sheared at `rate`.
SimulationSetup unitSphereShearBox(int n, double phi, double rate) {
  const PairMaterial mat = frictionlessUnitMass(1e5 * 6.0 / M_PI, 0.9);
  const double side = std::cbrt(n * M_PI / 6.0 / phi);
  return periodicCube(mat, side, linearContactTime(mat.kn, mat.gammaN, 0.5) / 50.0, rate);
}

// n spheres at random in the box of `s`, on its streaming profile plus Maxwellian fluctuations of
// unit temperature: hot enough to collide across the shearing boundary within a strain unit.
Particles hotShearedGas(const SimulationSetup& s, int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Particles p = shearedUnitSpheres(s, randomCentres(s, n, 0.5, rng));
  std::normal_distribution<double> thermal(0.0, 1.0);
  for (std::size_t i = 0; i < p.nOwned; ++i) p.v[i] += Vec3(thermal(rng), thermal(rng), thermal(rng));
  return p;
}

// Runs `steps` recorded steps, asserting at each that the contacts the force loop found are
// every touching pair of the Lees-Edwards images; adds them up in `contacts`.
void expectEveryTouchingPairFound(Simulation& sim, std::int64_t steps, std::size_t& contacts) {
  const double side = sim.boxHigh()[1] - sim.boxLow()[1];
  for (std::int64_t k = 0; k < steps; ++k) {
    sim.step(/*recordContacts=*/true);
    const std::size_t found = sim.frame().contacts.size();
    ASSERT_EQ(found, touchingPairsSheared(sim.particles(), side, sim.shearOffset(sim.time()))) << "step " << k + 1;
    contacts += found;
  }
}

}  // namespace

// A hot sheared gas: at every step the contacts the force loop finds are every touching pair of
// the Lees-Edwards images, over many list builds and a strain of 2 (the offset goes round the
// box's length 2 times), while the list is rebuilt much less often than the offset drifts half
// the skin.
TEST(LeesEdwards, AShearedGasListsEveryTouchingPairAcrossItsImages) {
  const SimulationSetup s = unitSphereShearBox(250, 0.3, 5.0);
  Simulation sim(s, hotShearedGas(s, 250, 17));
  const std::int64_t steps = static_cast<std::int64_t>(std::ceil(2.0 / (s.shearRate * s.dt)));
  std::size_t contacts = 0;
  expectEveryTouchingPairFound(sim, steps, contacts);
  EXPECT_GT(contacts, static_cast<std::size_t>(steps)) << "a gas that collides";
  const double stepsPerHalfSkinDrift = 0.15 / (s.shearRate * (s.hi[1] - s.lo[1]) * s.dt);
  EXPECT_GT(static_cast<double>(steps) / static_cast<double>(sim.rebuilds()), 3.0 * stepsPerHalfSkinDrift)
      << sim.rebuilds() << " list builds in " << steps << " steps";
}

// Between list builds a particle that crossed the shearing boundary sits outside the box as its
// image, with the image's lab-frame velocity; the frame and the energies show the particle inside
// the box (LeesEdwardsImage.hpp), so neither depends on when the list was last built, and the
// contact points it recorded move with it (extract reads r_i - c as a lever arm).
TEST(LeesEdwards, FramesAndEnergiesShowEveryParticleInsideTheBox) {
  const SimulationSetup s = unitSphereShearBox(250, 0.2, 2.0);
  const double side = s.hi[1] - s.lo[1];
  Simulation sim(s, hotShearedGas(s, 250, 23));
  int outside = 0;
  int shownContacts = 0;  // contacts of a particle the frame shows as another image
  for (int k = 0; k < 20000 && (outside < 20 || shownContacts < 5); ++k) {
    sim.step(/*recordContacts=*/true);
    const auto& q = sim.particles();
    bool someOutside = false;
    for (std::size_t i = 0; i < q.nOwned; ++i) someOutside |= q.x[i][1] < 0.0 || q.x[i][1] >= side;
    if (!someOutside) continue;
    ++outside;
    const auto f = sim.frame();
    double kinetic = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      ASSERT_GE(f.position[i][1], 0.0);
      ASSERT_LT(f.position[i][1], side);
      ASSERT_GE(f.position[i][0], 0.0);
      ASSERT_LT(f.position[i][0], side);
      // The velocity about the streaming profile is the particle's, whichever image shows it.
      const std::size_t j = *sim.indexOf(f.id[i]);
      const double profileHere = s.shearRate * (f.position[i][1] - 0.5 * side);
      const double profileThere = s.shearRate * (q.x[j][1] - 0.5 * side);
      EXPECT_NEAR(f.velocity[i][0] - profileHere, q.v[j][0] - profileThere, 1e-12 * side * s.shearRate);
      kinetic += 0.5 * f.mass[i] * f.velocity[i].squaredNorm();
    }
    EXPECT_NEAR(sim.energies().translational, kinetic, 1e-12 * kinetic);
    for (std::size_t c = 0; c < f.contacts.size(); ++c) {
      const std::size_t i = *sim.indexOf(f.contacts.i[c]);  // frames list the owned particles in order
      if (f.position[i] != q.x[i]) ++shownContacts;
      // The contact point x_i - a_i n lies a radius from the centre shown.
      EXPECT_NEAR((f.position[i] - f.contacts.contactPoint[c]).norm(), 0.5, 1e-9) << "contact " << c;
    }
  }
  EXPECT_GE(outside, 20) << "no step with a particle outside the box between builds";
  EXPECT_GE(shownContacts, 5) << "no contact of a particle shown as another image";
}

// A sheared crystal (an fcc lattice of 108 spheres at solid fraction 0.68, every sphere touching
// or nearly touching its twelve neighbours): persistent contacts across the shearing boundary,
// every one of them found at every step over half a strain unit.
TEST(LeesEdwards, AShearedCrystalListsEveryTouchingPair) {
  const int n = 108;
  const SimulationSetup s = unitSphereShearBox(n, 0.68, 1.0);
  std::mt19937_64 rng(29);
  Simulation sim(s, shearedUnitSpheres(s, fccLatticeSites(s.lo, s.hi, n, 1.0, rng)));
  const std::int64_t steps = static_cast<std::int64_t>(std::ceil(0.5 / (s.shearRate * s.dt)));
  std::size_t contacts = 0;
  expectEveryTouchingPairFound(sim, steps, contacts);
  EXPECT_GT(contacts, static_cast<std::size_t>(steps) * n) << "a crystal in contact";
}
