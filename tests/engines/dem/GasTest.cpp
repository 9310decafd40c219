// Granular gases in a fully periodic box, no gravity (VALIDATION.md DEM):
// - elastic (gamma = 0, mu = 0) gas of 2000 spheres: relative energy error below 1e-4 at
//   dt = t_c/50 over 1e5 steps, linear momentum conserved to round-off; the O(dt^2) order of the
//   energy error is measured per collision (see ElasticCollisionEnergyErrorIsSecondOrder);
// - homogeneous cooling of an inelastic frictionless gas (e = 0.9, solid fraction 0.1): Haff's
//   law with tau from the collisional dissipation of Eq. 5.7.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

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

PairMaterial elastic() {
  PairMaterial m;
  m.kn = 2e5;  // Table 6.1; no dashpots, no friction
  return m;
}

double sumMassSpeed(const Particles& p) {
  double s = 0.0;
  for (std::size_t i = 0; i < p.nOwned; ++i) s += p.mass[i] * p.v[i].norm();
  return s;
}

}  // namespace

TEST(ElasticGas, EnergyAndMomentumOver1e5Steps) {
  // 2000 spheres (d = 1), solid fraction 0.1, T0 = 1 (v ~ sqrt(g d0)): about 17 collisions per
  // particle over the run, dt = t_c/50 exactly.
  const PairMaterial m = elastic();
  const double meff = 0.5 * sphereMass(1.0, 1.91);
  const double dt = linearContactTime(m.kn, 0.0, meff) / 50.0;
  Gas g = periodicGas(2000, 0.1, 1.0, m, dt, 1);
  Simulation sim(g.setup, g.particles);
  auto energy = [&] { return sim.energies().kinetic() + elasticEnergy(sim.frame(), m); };
  const double e0 = energy();
  const Vec3 p0 = sim.momentum();
  double worst = 0.0;
  double worstMomentum = 0.0;
  for (int s = 1; s <= 100000; ++s) {
    const bool sample = s % 50 == 0;
    sim.step(sample);
    if (!sample) continue;
    worst = std::max(worst, std::abs(energy() - e0) / e0);
    worstMomentum = std::max(worstMomentum, (sim.momentum() - p0).norm() / sumMassSpeed(sim.particles()));
  }
  std::printf("elastic gas, 1e5 steps at t_c/50: max |E - E0|/E0 %.3e, max |P - P0| / sum m|v| %.2e\n", worst,
              worstMomentum);
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(worstMomentum, 1e-13);
  EXPECT_GT(worst, 0.0);  // collisions happened
  const std::string setup =
      formatNote("2000 spheres, solid fraction 0.1, T0 = 1, dt = t_c/50 = %.4e t0, 1e5 steps", dt);
  recordValidation({"dem.gas.elastic.energy_error", kSection,
                    "elastic frictionless gas in a periodic box: max |E - E0| / E0 over 1e5 steps at dt = t_c/50",
                    "VALIDATION.md DEM (elastic gas)", 0.0, worst, "below 1e-4", worst < 1e-4 && worst > 0.0,
                    setup + "; E includes the elastic energy of the contacts"});
  recordValidation({"dem.gas.elastic.momentum", kSection,
                    "elastic frictionless gas in a periodic box: max |P - P0| / sum m|v| over 1e5 steps",
                    "VALIDATION.md DEM (elastic gas)", 0.0, worstMomentum, "round-off (1e-13)", worstMomentum < 1e-13,
                    setup});
}

TEST(ElasticGas, CollisionEnergyErrorIsSecondOrder) {
  // VALIDATION.md asks that halving dt quarter the gas's energy error (within 20 %). In the gas
  // that error is a random walk: each collision leaves an O(dt^2) error of either sign, set by
  // where in a step the contact begins and ends, so one run at dt and one at dt/2 give ratios
  // anywhere from ~1 to ~8 (measured over seeds; see the report). The order itself is a property
  // of each collision: over an ensemble of binary collisions of the gas's spheres with random
  // impact parameter, entry phase and dt in [t_c/51, t_c/50] (so the exit phase is not locked
  // to the entry phase, as it is when t_c/dt is an integer), the RMS relative energy error
  // quarters when dt halves.
  const PairMaterial m = elastic();
  const double mass = sphereMass(1.0, 1.91);
  const double tc = linearContactTime(m.kn, 0.0, 0.5 * mass);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto collide = [&](double dt, double b, double entry) {
    Particles p;
    // Relative velocity 1 along x, impact parameter b (contact diameter 1), first touch at
    // t = entry exactly.
    const double x0 = std::sqrt(1.0 - b * b) + entry;
    p.addOwned(0, 0, 0.5, mass, Vec3(-0.5 * x0, -0.5 * b, 0), Vec3(0.5, 0, 0), Vec3::Zero(), false);
    p.addOwned(1, 0, 0.5, mass, Vec3(0.5 * x0, 0.5 * b, 0), Vec3(-0.5, 0, 0), Vec3::Zero(), false);
    SimulationSetup setup = openBox(m, 1, dt);
    setup.lo = Vec3::Constant(-3.0);  // small box: a cheap neighbour grid
    setup.hi = Vec3::Constant(3.0);
    Simulation sim(setup, p);
    const double e0 = sim.energies().kinetic();
    bool touched = false;
    while (!(touched && sim.contactCount() == 0)) {
      sim.step();
      touched = touched || sim.contactCount() > 0;
    }
    return sim.energies().kinetic() / e0 - 1.0;
  };
  double sumCoarse = 0.0;
  double sumFine = 0.0;
  const int n = 2000;  // the RMS ratio then carries ~2 % statistical noise
  for (int k = 0; k < n; ++k) {
    const double dt = tc / (50.0 + u(rng));
    const double b = 0.95 * std::sqrt(u(rng));  // uniform over the collision cross-section
    const double entry = dt * (5.0 + u(rng));
    const double coarse = collide(dt, b, entry);
    const double fine = collide(0.5 * dt, b, entry);
    sumCoarse += coarse * coarse;
    sumFine += fine * fine;
  }
  const double rmsCoarse = std::sqrt(sumCoarse / n);
  const double rmsFine = std::sqrt(sumFine / n);
  std::printf("binary elastic collisions: RMS relative energy error %.3e (dt ~ t_c/50), %.3e (dt/2), ratio %.3f\n",
              rmsCoarse, rmsFine, rmsCoarse / rmsFine);
  EXPECT_NEAR(rmsCoarse / rmsFine, 4.0, 0.8);
  recordValidation(
      {"dem.gas.elastic.energy_order", kSection,
       "elastic collisions of the gas's spheres: ratio of the RMS relative energy errors at dt and dt/2 (dt^2: 4)",
       "VALIDATION.md DEM (elastic gas)", 4.0, rmsCoarse / rmsFine, "20 %", std::abs(rmsCoarse / rmsFine - 4.0) <= 0.8,
       formatNote("measured per collision over %d binary collisions (random impact parameter, entry phase, dt in "
                  "[t_c/51, t_c/50]), not on one gas run, whose dt/dt2 ratio is a random walk of either-sign errors "
                  "(~1 to ~8); RMS %.3e at dt, %.3e at dt/2",
                  n, rmsCoarse, rmsFine)});
}

TEST(HomogeneousCooling, FollowsHaffsLawWithEq57Dissipation) {
  // Inelastic (e = 0.9 from gamma_n by inverting Eqs. 6.9-6.10), frictionless gas, 2000 spheres,
  // solid fraction phi = 0.1, no gravity. Conventions: T = <C^2>/3 (Eq. 5.6, per unit mass), the
  // fluctuation energy density is (3/2) rho_p phi T, and Eq. 5.7 dissipates
  //   J = (12/sqrt(pi)) (1 - e^2) rho_p phi^2 g0 T^(3/2) / d,
  // with the Carnahan-Starling g0 = (1 - phi/2) / (1 - phi)^3. Homogeneous, (3/2) rho_p phi dT/dt = -J:
  //   dT/dt = -(8/sqrt(pi)) (1 - e^2) phi g0 T^(3/2) / d
  // whose solution is Haff's law T = T0 / (1 + t/tau)^2 with
  //   tau = sqrt(pi) d / (4 (1 - e^2) phi g0 sqrt(T0)).
  // T^(-1/2) is then linear in t; a least-squares line through it gives tau = intercept / slope.
  const double e = 0.9;
  const double phi = 0.1;
  const double T0 = 4.0;  // v ~ 3.5 sqrt(g d0): overlaps < 1 % of d, contacts take ~2 % of the time
  const double mass = sphereMass(1.0, 1.91);
  PairMaterial m;
  m.kn = 2e5;
  m.gammaN = gammaForRestitution(e, m.kn, 0.5 * mass);
  const double dt = linearContactTime(m.kn, m.gammaN, 0.5 * mass) / 50.0;
  const double g0 = (1.0 - 0.5 * phi) / std::pow(1.0 - phi, 3);
  const double tauPredicted = std::sqrt(M_PI) / (4.0 * (1.0 - e * e) * phi * g0 * std::sqrt(T0));

  Gas g = periodicGas(2000, phi, T0, m, dt, 3);
  Simulation sim(g.setup, g.particles);
  std::vector<double> t{0.0};
  std::vector<double> y{1.0 / std::sqrt(granularTemperature(sim.particles()))};
  const auto every = static_cast<std::int64_t>(std::llround(0.05 * tauPredicted / dt));
  while (sim.time() < 2.0 * tauPredicted) {  // T falls to about T0/9
    sim.run(every);
    t.push_back(sim.time());
    y.push_back(1.0 / std::sqrt(granularTemperature(sim.particles())));
  }
  double st = 0, sy = 0, stt = 0, sty = 0;
  const double n = static_cast<double>(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    st += t[k];
    sy += y[k];
    stt += t[k] * t[k];
    sty += t[k] * y[k];
  }
  const double slope = (n * sty - st * sy) / (n * stt - st * st);
  const double intercept = (sy - slope * st) / n;
  const double tauFit = intercept / slope;
  double worstLine = 0.0;  // how straight T^(-1/2) is: largest relative residual of the line
  for (std::size_t k = 0; k < t.size(); ++k) {
    worstLine = std::max(worstLine, std::abs(y[k] - (intercept + slope * t[k])) / y[k]);
  }
  std::printf("Haff: tau fitted %.4f, predicted %.4f (ratio %.4f); T(end)/T0 %.4f; largest residual of the line %.2e\n",
              tauFit, tauPredicted, tauFit / tauPredicted, std::pow(y.front() / y.back(), 2), worstLine);
  EXPECT_NEAR(tauFit, tauPredicted, 0.1 * tauPredicted);
  EXPECT_LT(worstLine, 0.02);  // the decay has Haff's form
  recordValidation(
      {"dem.gas.haff.tau", kSection,
       "homogeneous cooling of an inelastic frictionless gas: Haff time tau fitted to T^(-1/2) against Eq. 5.7",
       "Haff's law with Eq. 5.7 dissipation (Carnahan-Starling g0)", tauPredicted, tauFit, "within 10 %",
       std::abs(tauFit - tauPredicted) <= 0.1 * tauPredicted && worstLine < 0.02,
       formatNote("2000 spheres, solid fraction 0.1, e = 0.9, mu = 0, T0 = 4, dt = t_c/50, fit over 2 tau (T falls to "
                  "%.3f T0); largest relative residual of the T^(-1/2) line %.2e (below 2e-2 required)",
                  std::pow(y.front() / y.back(), 2), worstLine)});
}
