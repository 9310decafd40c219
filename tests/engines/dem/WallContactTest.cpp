// Particle-wall contacts with Table 6.1 wall coefficients (k_n = 2e5, k_t = 2/7 k_n, gamma_n = 40,
// gamma_t = 20, mu_wall = 0.5; reduced units d0 = m0 = g = 1), the VALIDATION.md DEM checks:
// - sliding sphere on a frictional plane ends rolling at 5/7 of its initial speed;
// - free fall and bounce height from e_n of the particle-wall pair (Eqs. 6.9-6.10, m_eff = m);
// - oblique impacts at 0-89 degrees never gain kinetic energy, and in gross sliding rebound with
//   v_t' = v_t - mu (1 + e) v_n, omega' = 5 mu (1 + e) v_n / (2 a);
// - a vibrating wall's velocity enters the relative velocity (Eqs. 6.2-6.4) like a particle's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tests/engines/dem/DemTestSupport.hpp"
#include "tests/support/ValidationNote.hpp"
#include "tests/support/ValidationRecord.hpp"

using namespace grainbridge;
using namespace grainbridge::dem;
using namespace grainbridge::dem::testing;
using grainbridge::testing::formatNote;
using grainbridge::testing::recordValidation;

namespace {

constexpr const char* kSection = "DEM (Chapter 6)";

constexpr double kA = 0.5;  // small particle of Table 6.1: d = 1, density 1.91
const double kMass = sphereMass(1.0, 1.91);

// One small particle above a floor wall (Table 6.1 wall material, friction mu).
Simulation singleOnFloor(const Vec3& x, const Vec3& v, double mu, const Vec3& gravity, const Wall* wall = nullptr) {
  SimulationSetup setup = openBox(table61Particle());
  setup.gravity = gravity;
  setup.walls.push_back(wall != nullptr ? *wall : floorWall(table61Wall(mu)));
  Particles p;
  p.addOwned(0, 0, kA, kMass, x, v, Vec3::Zero(), false);
  return Simulation(setup, p);
}

double kineticEnergy(const Simulation& sim) { return sim.energies().kinetic(); }

// e_n of the particle-wall pair, Eqs. 6.9-6.10 with m_eff = m (infinite wall mass).
double wallRestitution() {
  const PairMaterial w = table61Wall();
  return linearRestitution(w.kn, w.gammaN, kMass);
}

}  // namespace

TEST(WallContact, SlidingSphereEndsRollingAtFiveSevenths) {
  // Starts resting at its equilibrium overlap m g / k_n (no bounce), sliding at v0 without spin.
  // Friction at the contact conserves the angular momentum about the contact point,
  // m a v + I omega, so rolling (v = a omega) sets in at v = 5/7 v0 whatever mu is.
  const double v0 = 1.0;
  const double overlap = kMass / table61Wall().kn;
  Simulation sim = singleOnFloor(Vec3(0, 0, kA - overlap), Vec3(v0, 0, 0), 0.5, Vec3(0, 0, -1));
  sim.run(15000);  // 3 t0; sliding stops after 2 v0 / (7 mu g) = 0.57 t0
  const auto& p = sim.particles();
  std::printf("rolling: v %.6f (5/7 = %.6f), a omega_y %.6f, z drift %.2e\n", p.v[0].x(), 5.0 / 7.0 * v0,
              kA * p.omega[0].y(), p.x[0].z() - (kA - overlap));
  EXPECT_NEAR(p.v[0].x(), 5.0 / 7.0 * v0, 0.01 * 5.0 / 7.0 * v0);
  EXPECT_NEAR(kA * p.omega[0].y(), p.v[0].x(), 0.01 * p.v[0].x());  // rolling without slip
  EXPECT_NEAR(p.x[0].z(), kA - overlap, 1e-6);                      // stayed on the plane
  const bool rolling = std::abs(p.v[0].x() - 5.0 / 7.0 * v0) <= 0.01 * 5.0 / 7.0 * v0 &&
                       std::abs(kA * p.omega[0].y() - p.v[0].x()) <= 0.01 * p.v[0].x();
  recordValidation({"dem.wall.slide_to_roll", kSection,
                    "sliding sphere on a frictional plane (mu_wall = 0.5) ends rolling: final speed over initial",
                    "VALIDATION.md DEM (angular momentum about the contact point)", 5.0 / 7.0, p.v[0].x() / v0, "1 %",
                    rolling,
                    formatNote("rolling without slip: a omega_y / v = %.6f (within 1 %% required); 15000 steps of "
                               "2e-4 t0",
                               kA * p.omega[0].y() / p.v[0].x())});
}

TEST(WallContact, FreeFallAndBounceHeightFollowRestitution) {
  // Free fall is exact under velocity Verlet (constant force); each apex of the gap is e_n^2 times
  // the previous one, e_n from Eqs. 6.9-6.10 with m_eff = m.
  const double h0 = 2.0;
  Simulation sim = singleOnFloor(Vec3(0, 0, kA + h0), Vec3::Zero(), 0.5, Vec3(0, 0, -1));
  const auto& p = sim.particles();
  double maxFreeFallError = 0.0;
  while (p.x[0].z() - kA > 0.0) {
    const double t = sim.time();
    maxFreeFallError = std::max(maxFreeFallError, std::abs(p.x[0].z() - (kA + h0 - 0.5 * t * t)));
    sim.step();
  }
  EXPECT_LT(maxFreeFallError, 1e-12);
  recordValidation({"dem.wall.free_fall", kSection,
                    "free fall from 2 d0: largest deviation of the height from h0 - g t^2 / 2, in d0",
                    "VALIDATION.md DEM (free fall and bounce height)", 0.0, maxFreeFallError,
                    "1e-12 (exact under velocity Verlet)", maxFreeFallError < 1e-12, "dt = 2e-4 t0"});
  const double e = wallRestitution();
  double previous = h0;
  for (int bounce = 1; bounce <= 2; ++bounce) {
    while (p.v[0].z() <= 0.0) sim.step();  // through the contact
    double apex = p.x[0].z() - kA;
    while (p.v[0].z() > 0.0) {
      sim.step();
      apex = std::max(apex, p.x[0].z() - kA);
    }
    std::printf("bounce %d: apex %.6f, ratio %.6f vs e_n^2 = %.6f (e_n = %.6f)\n", bounce, apex, apex / previous, e * e,
                e);
    EXPECT_NEAR(apex / previous, e * e, 0.01 * e * e) << "bounce " << bounce;
    recordValidation(
        {formatNote("dem.wall.bounce_height.bounce%d", bounce), kSection,
         formatNote("bounce %d: apex height over the previous one, against e_n^2 of the particle-wall pair", bounce),
         "Eqs. 6.9-6.10 with m_eff = m, Table 6.1 wall", e * e, apex / previous, "1 %",
         std::abs(apex / previous - e * e) <= 0.01 * e * e,
         formatNote("e_n = %.6f; apex %.6f d0 after %.6f d0; dt = 2e-4 t0", e, apex, previous)});
    previous = apex;
  }
}

TEST(WallContact, ObliqueImpactsNeverGainEnergyAndSlideAsPredicted) {
  // Unit speed at angle theta from the wall normal, no spin, no gravity. Gross sliding (the
  // contact slides throughout) holds when v_t / v_n > 7/2 mu (1 + e) (about 73 degrees here).
  const double mu = 0.5;
  const double e = wallRestitution();
  std::vector<double> angles;
  for (int deg = 0; deg <= 85; deg += 5) angles.push_back(deg);
  angles.push_back(89);
  for (double deg : angles) {
    const double th = deg * M_PI / 180.0;
    const double vt = std::sin(th);
    const double vn = std::cos(th);
    Simulation sim = singleOnFloor(Vec3(0, 0, kA + 0.01), Vec3(vt, 0, -vn), mu, Vec3::Zero());
    const auto& p = sim.particles();
    const double before = kineticEnergy(sim);
    double worst = before;  // largest kinetic energy seen after the contact began
    bool touched = false;
    while (!(touched && p.x[0].z() > kA)) {
      sim.step();
      touched = touched || p.x[0].z() < kA;
      if (touched) worst = std::max(worst, kineticEnergy(sim));
    }
    const double after = kineticEnergy(sim);
    EXPECT_LE(after, before) << deg << " degrees";
    EXPECT_LE(worst, before) << deg << " degrees";
    recordValidation({formatNote("dem.wall.oblique.energy.deg%.0f", deg), kSection,
                      formatNote("oblique impact at %.0f degrees on a frictional wall (mu = 0.5): kinetic energy "
                                 "(translational + rotational) after the rebound against the energy before",
                                 deg),
                      "VALIDATION.md DEM (oblique impacts)", before, after, "never increases (also during contact)",
                      after <= before && worst <= before,
                      formatNote("largest kinetic energy from first touch on %.6f (not above the energy before "
                                 "required); unit impact speed, no spin, dt = 2e-4 t0",
                                 worst)});
    if (vt / vn > 3.5 * mu * (1.0 + e) * 1.1) {
      const double vtPredicted = vt - mu * (1.0 + e) * vn;
      const double omegaPredicted = 5.0 * mu * (1.0 + e) * vn / (2.0 * kA);
      std::printf(
          "%4.0f deg: v_t' %.6f (pred %.6f), omega' %.6f (pred %.6f), v_n'/v_n %.5f (e %.5f), KE %.4f -> %.4f\n", deg,
          p.v[0].x(), vtPredicted, p.omega[0].y(), omegaPredicted, p.v[0].z() / vn, e, before, after);
      EXPECT_NEAR(p.v[0].x(), vtPredicted, 0.01 * vtPredicted) << deg << " degrees";
      EXPECT_NEAR(p.omega[0].y(), omegaPredicted, 0.01 * omegaPredicted) << deg << " degrees";
      const std::string gross = formatNote("gross sliding at %.0f degrees (mu = 0.5, e_n = %.5f)", deg, e);
      recordValidation({formatNote("dem.wall.oblique.gross_sliding.vt.deg%.0f", deg), kSection,
                        "rebound tangential velocity v_t' = v_t - mu (1 + e) v_n, " + gross,
                        "VALIDATION.md DEM (oblique impacts)", vtPredicted, p.v[0].x(), "1 %",
                        std::abs(p.v[0].x() - vtPredicted) <= 0.01 * vtPredicted, "unit impact speed, no spin"});
      recordValidation({formatNote("dem.wall.oblique.gross_sliding.omega.deg%.0f", deg), kSection,
                        "rebound spin omega' = 5 mu (1 + e) v_n / (2 a), " + gross,
                        "VALIDATION.md DEM (oblique impacts)", omegaPredicted, p.omega[0].y(), "1 %",
                        std::abs(p.omega[0].y() - omegaPredicted) <= 0.01 * omegaPredicted,
                        "unit impact speed, no spin"});
    } else {
      std::printf("%4.0f deg: KE %.6f -> %.6f\n", deg, before, after);
    }
  }
}

TEST(WallContact, ElasticObliqueImpactsNeverGainEnergy) {
  // The same sweep with no dashpots (gamma_n = gamma_t = 0): only Coulomb slip dissipates, so a
  // tangential spring that released more than it stored would show. dt = t_c/100 keeps the
  // integration error of the elastic normal collision (O(dt^2), ~1e-5) below the 1e-4 allowed.
  PairMaterial w = table61Wall();
  w.gammaN = 0.0;
  w.gammaT = 0.0;
  const double tc = linearContactTime(w.kn, 0.0, kMass);
  double worstGain = -1.0;
  for (int deg = 0; deg <= 89; deg += (deg < 85 ? 5 : 4)) {
    const double th = deg * M_PI / 180.0;
    SimulationSetup setup = openBox(table61Particle(), 1, tc / 100.0);
    Wall wall = floorWall(w);
    setup.walls.push_back(wall);
    Particles p;
    p.addOwned(0, 0, kA, kMass, Vec3(0, 0, kA + 0.01), Vec3(std::sin(th), 0, -std::cos(th)), Vec3::Zero(), false);
    Simulation sim(setup, p);
    const auto& q = sim.particles();
    const double before = kineticEnergy(sim);
    bool touched = false;
    while (!(touched && q.x[0].z() > kA)) {
      sim.step();
      touched = touched || q.x[0].z() < kA;
    }
    const double gain = kineticEnergy(sim) / before - 1.0;
    worstGain = std::max(worstGain, gain);
    EXPECT_LE(gain, 1e-4) << deg << " degrees";
    recordValidation({formatNote("dem.wall.oblique_elastic.energy.deg%d", deg), kSection,
                      formatNote("elastic (no dashpots) oblique impact at %d degrees on a frictional wall (mu = 0.5): "
                                 "relative change of the kinetic energy",
                                 deg),
                      "VALIDATION.md DEM (oblique impacts)", 0.0, gain, "never increases (1e-4 integration error)",
                      gain <= 1e-4, "dt = t_c/100; only Coulomb slip dissipates"});
  }
  std::printf("elastic oblique impacts: largest relative kinetic-energy change %.3e\n", worstGain);
}

TEST(WallContact, WallMovingUpLaunchesParticleAsInItsFrame) {
  // A plane vibrating as A sin(2 pi f t) along its normal, at t ~ 0 where its velocity is
  // V = 2 pi f A and its acceleration ~0 (2 pi f t_c ~ 4e-5: constant velocity to 1e-9),
  // meets a particle at rest: in the wall frame the particle arrives at V and leaves at e_n V,
  // so in the lab it leaves at (1 + e_n) V.
  const double V = 1.0;
  Wall wall = floorWall(table61Wall());
  wall.vibration.direction = Vec3::UnitZ();
  wall.vibration.frequency = 1e-3;
  wall.vibration.amplitude = V / (2.0 * M_PI * wall.vibration.frequency);
  Simulation sim = singleOnFloor(Vec3(0, 0, kA + 1e-3), Vec3::Zero(), 0.5, Vec3::Zero(), &wall);
  const auto& p = sim.particles();
  auto gap = [&] { return p.x[0].z() - kA - sim.setup().walls[0].positionAt(sim.time()).z(); };
  bool touched = false;
  while (!(touched && gap() > 0.0)) {
    sim.step();
    touched = touched || gap() < 0.0;
  }
  const double e = wallRestitution();
  std::printf("moving wall: particle leaves at %.6f, (1 + e) V = %.6f\n", p.v[0].z(), (1.0 + e) * V);
  EXPECT_NEAR(p.v[0].z(), (1.0 + e) * V, 0.01 * (1.0 + e) * V);
  recordValidation({"dem.wall.vibrating.normal_launch", kSection,
                    "wall moving along its normal at V meets a particle at rest: launch speed (1 + e_n) V",
                    "Eqs. 6.2-6.4 (the wall velocity enters the relative velocity)", (1.0 + e) * V, p.v[0].z(), "1 %",
                    std::abs(p.v[0].z() - (1.0 + e) * V) <= 0.01 * (1.0 + e) * V,
                    formatNote("V = 1 sqrt(g d0), e_n = %.6f", e)});
}

TEST(WallContact, SidewaysMovingWallDragsParticleToRolling) {
  // The floor moves sideways (vibration along x, in its own plane, at t ~ 0: velocity V, constant
  // to 2e-6 over the run) under a particle resting at its equilibrium overlap. In the wall frame
  // the particle slides at -V and ends rolling at -5/7 V, so in the lab it moves at 2/7 V with
  // a omega_y = -5/7 V: the wall velocity enters the tangential relative velocity (Eq. 6.3).
  const double V = 1.0;
  Wall wall = floorWall(table61Wall());
  wall.vibration.direction = Vec3::UnitX();
  wall.vibration.frequency = 1e-4;
  wall.vibration.amplitude = V / (2.0 * M_PI * wall.vibration.frequency);
  const double overlap = kMass / table61Wall().kn;
  Simulation sim = singleOnFloor(Vec3(0, 0, kA - overlap), Vec3::Zero(), 0.5, Vec3(0, 0, -1), &wall);
  sim.run(15000);
  const auto& p = sim.particles();
  std::printf("sideways wall: v %.6f (2/7 V = %.6f), a omega_y %.6f (-5/7 V = %.6f)\n", p.v[0].x(), 2.0 / 7.0 * V,
              kA * p.omega[0].y(), -5.0 / 7.0 * V);
  EXPECT_NEAR(p.v[0].x(), 2.0 / 7.0 * V, 0.01 * 2.0 / 7.0 * V);
  EXPECT_NEAR(kA * p.omega[0].y(), -5.0 / 7.0 * V, 0.01 * 5.0 / 7.0 * V);
  recordValidation({"dem.wall.vibrating.sideways_drag", kSection,
                    "floor moving in its own plane at V under a resting particle: final particle speed 2/7 V",
                    "Eq. 6.3 (the wall velocity enters the tangential relative velocity)", 2.0 / 7.0 * V, p.v[0].x(),
                    "1 %",
                    std::abs(p.v[0].x() - 2.0 / 7.0 * V) <= 0.01 * 2.0 / 7.0 * V &&
                        std::abs(kA * p.omega[0].y() + 5.0 / 7.0 * V) <= 0.01 * 5.0 / 7.0 * V,
                    formatNote("a omega_y = %.6f (-5/7 V = %.6f, within 1 %% required); V = 1 sqrt(g d0)",
                               kA * p.omega[0].y(), -5.0 / 7.0 * V)});
}
