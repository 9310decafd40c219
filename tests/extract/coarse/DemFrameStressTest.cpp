// Eq. 2.3 on frames of the DEM engine equals the whole-domain stress the engine prints
// (grainbridge::dem::wholeDomainStress) to round-off: a periodic gas with contacts, spheres
// landing on a floor (wall contacts: the wall as j at the contact point), and Lees-Edwards shear.
// Coarse graining on a one-cell grid gives the same tensor, and the cells of a finer grid add
// up to the whole-domain contact stress for every kernel. Links engines_dem in the test only.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "engines/dem/DomainStress.hpp"
#include "engines/dem/Insertion.hpp"
#include "extract/coarse/CoarseGrain.hpp"
#include "extract/coarse/DomainAverages.hpp"
#include "tests/engines/dem/DemTestSupport.hpp"
#include "tests/support/ValidationNote.hpp"
#include "tests/support/ValidationRecord.hpp"

using namespace grainbridge;
using namespace grainbridge::dem::testing;
namespace coarse = grainbridge::extract::coarse;

namespace {

double boxVolume(const core::data::ParticleFrame& f) { return (f.domain.hi - f.domain.lo).prod(); }

// Returns the relative error, for the validation record.
double expectRoundOff(const Mat3& got, const Mat3& want, const char* what) {
  const double relative = (got - want).norm() / want.norm();
  std::printf("  %s: |got - reference| / |reference| = %.1e\n", what, relative);
  EXPECT_LT(relative, 1e-12) << what << "\n" << got << "\nreference\n" << want;
  return relative;
}

// The engine's stress against Eq. 2.3 on its frame, whole domain and one bin: the mean normal
// stress is shown, the whole tensor compared.
void recordFrameStress(const std::string& id, const std::string& check, const Mat3& reference, const Mat3& ours,
                       double wholeDomain, double oneBin, const std::string& note) {
  grainbridge::testing::recordValidation(
      {id, "Extraction (Section 2.3, Sections 6.3.2-6.3.3)", check, "Eq. 2.3; grainbridge::dem::wholeDomainStress",
       reference.trace() / 3.0, ours.trace() / 3.0, "round-off (1e-12)", wholeDomain < 1e-12 && oneBin < 1e-12,
       grainbridge::testing::formatNote("mean normal stress tr(sigma)/3 shown; whole tensor compared: relative "
                                        "Frobenius error %.1e over the whole domain, %.1e on a one-cell grid; ",
                                        wholeDomain, oneBin) +
           note});
}

core::data::ParticleFrame periodicGasFrame() {
  const dem::PairMaterial m = table61Particle();
  Gas g = periodicGas(600, 0.35, 4.0, m, 2e-4, 5);
  dem::Simulation sim(g.setup, g.particles);
  sim.run(300);
  sim.step(true);
  return sim.frame();
}

// Spheres settling on a floor wall in a box periodic in x and y (a few layers deep), with
// background damping (Eq. 6.7) so that they are resting on the wall when the frame is taken.
core::data::ParticleFrame floorFrame() {
  dem::SimulationSetup s = openBox(table61Particle());
  s.lo = Vec3(-2, -2, -1);
  s.hi = Vec3(2, 2, 20);
  s.periodic = {true, true, false};
  s.gravity = Vec3(0, 0, -1);
  s.backgroundDamping = 1.0;
  s.walls.push_back(floorWall(table61Wall()));
  dem::InsertionRequest rq;
  rq.lo = Vec3(-2, -2, 0.55);
  rq.hi = Vec3(2, 2, 7.5);
  rq.periodic = {true, true, false};
  rq.radii.assign(60, 0.5);
  std::mt19937_64 rng(8);
  const auto centres = dem::insertRandomly(rq, rng);
  dem::Particles p;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    p.addOwned(static_cast<std::int64_t>(i), 0, 0.5, sphereMass(1.0, 1.91), centres[i], Vec3(0.1, 0, -2), Vec3::Zero(),
               false);
  }
  dem::Simulation sim(s, p);
  sim.run(27000);  // settled by t = 5.4 t0
  sim.step(true);
  return sim.frame();
}

core::data::ParticleFrame shearFrame() {
  const double rho = 6.0 / M_PI;  // d = 1, m = 1
  const dem::PairMaterial mat = frictionlessUnitMass(1e5 * rho, 0.9);
  const double box = std::cbrt(250 * M_PI / 6.0 / 0.35);
  const dem::SimulationSetup s = periodicCube(mat, box, dem::linearContactTime(mat.kn, mat.gammaN, 0.5) / 50.0, 1.0);
  std::mt19937_64 rng(4);
  const auto centres = randomCentres(s, 250, 0.5, rng);
  std::normal_distribution<double> noise(0.0, 0.3);
  dem::Particles p;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Vec3 v(s.shearRate * (centres[i][1] - 0.5 * box) + noise(rng), noise(rng), noise(rng));
    p.addOwned(static_cast<std::int64_t>(i), 0, 0.5, 1.0, centres[i], v, Vec3::Zero(), false);
  }
  dem::Simulation sim(s, p);
  sim.run(1500);
  sim.step(true);
  return sim.frame();
}

}  // namespace

TEST(DemFrameStress, PeriodicGasMatchesTheEngineAndCellsAddUp) {
  const auto f = periodicGasFrame();
  ASSERT_GT(f.contacts.size(), 20u);
  const Mat3 engine = dem::wholeDomainStress(f, boxVolume(f));
  const auto avg = coarse::averageWholeDomain(f);
  const double wholeDomain = expectRoundOff(avg.stress, engine, "whole domain");
  const core::grid::CellGrid one(f.domain.lo, f.domain.hi, {1, 1, 1}, {true, true, true});
  const double oneBin =
      expectRoundOff(coarse::coarseGrain(f, one, coarse::CoarseGrainingKernel::bin()).stress[0], engine, "one bin");
  recordFrameStress(
      "extract.dem_frame_stress.periodic_gas",
      "Eq. 2.3 on a DEM frame of a periodic gas with contacts against the whole-domain stress the "
      "engine prints",
      engine, avg.stress, wholeDomain, oneBin,
      grainbridge::testing::formatNote("600 spheres, solid fraction 0.35, %zu contacts", f.contacts.size()));

  const core::grid::CellGrid grid(f.domain.lo, f.domain.hi, {3, 3, 3}, {true, true, true});
  for (const auto& kernel : {coarse::CoarseGrainingKernel::bin(), coarse::CoarseGrainingKernel::overlap(),
                             coarse::CoarseGrainingKernel::gaussian(1.0), coarse::CoarseGrainingKernel::lucy(1.0)}) {
    const auto cg = coarse::coarseGrain(f, grid, kernel);
    Mat3 sum = Mat3::Zero();
    for (const Mat3& s : cg.contactStress) sum += s * grid.cellVolume();
    expectRoundOff(sum / boxVolume(f), avg.contactStress, kernel.name().c_str());
  }
}

TEST(DemFrameStress, WallContactsCountWithTheWallAsJAtTheContactPoint) {
  const auto f = floorFrame();
  ASSERT_GT(f.wallContacts.size(), 8u);
  ASSERT_GT(f.contacts.size(), 40u);
  const Mat3 engine = dem::wholeDomainStress(f, boxVolume(f));
  const Mat3 extracted = coarse::averageWholeDomain(f).stress;
  const double wholeDomain = expectRoundOff(extracted, engine, "whole domain");
  const core::grid::CellGrid one(f.domain.lo, f.domain.hi, {1, 1, 1}, {true, true, false});
  const double oneBin =
      expectRoundOff(coarse::coarseGrain(f, one, coarse::CoarseGrainingKernel::bin()).stress[0], engine, "one bin");
  recordFrameStress("extract.dem_frame_stress.wall_contacts",
                    "Eq. 2.3 on a DEM frame of spheres settled on a floor wall (the wall as j at the contact point) "
                    "against the whole-domain stress the engine prints",
                    engine, extracted, wholeDomain, oneBin,
                    grainbridge::testing::formatNote("%zu wall contacts, %zu pair contacts", f.wallContacts.size(),
                                                     f.contacts.size()));
  std::printf("settled bed: %zu wall contacts, %zu pair contacts, sigma_zz %.4g\n", f.wallContacts.size(),
              f.contacts.size(), engine(2, 2));
}

TEST(DemFrameStress, LeesEdwardsMatchesTheEngineToRoundOff) {
  // Both take C about the mean peculiar velocity v - u_LE, u_x = gammadot (y - y_mid). (Before
  // dem impl_version 3 the engine subtracted the mean of v itself, which is shifted by
  // a = gammadot (<y>_m - y_mid) and put an extra M a^2 / V into xx; this frame's a is not
  // zero, so that error would show here.)
  const auto f = shearFrame();
  ASSERT_GT(f.contacts.size(), 3u);
  const double volume = boxVolume(f);
  const Mat3 engine = dem::wholeDomainStress(f, volume);
  const auto avg = coarse::averageWholeDomain(f);
  double mass = 0.0, my = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    mass += f.mass[i];
    my += f.mass[i] * f.position[i][1];
  }
  const double a = f.domain.leesEdwardsShearRate * (my / mass - 0.5 * (f.domain.lo[1] + f.domain.hi[1]));
  ASSERT_GT(mass * a * a / volume, 1e-9 * std::abs(engine(0, 0)));  // the old error would be visible
  const double wholeDomain = expectRoundOff(avg.stress, engine, "whole domain");
  const core::grid::CellGrid one(f.domain.lo, f.domain.hi, {1, 1, 1}, {true, true, true});
  const double oneBin =
      expectRoundOff(coarse::coarseGrain(f, one, coarse::CoarseGrainingKernel::bin()).stress[0], engine, "one bin");
  recordFrameStress("extract.dem_frame_stress.lees_edwards",
                    "Eq. 2.3 on a DEM frame of Lees-Edwards shear against the whole-domain stress the engine prints",
                    engine, avg.stress, wholeDomain, oneBin,
                    grainbridge::testing::formatNote(
                        "C about the mean peculiar velocity in both; a = gammadot (<y>_m - y_mid) = %.3e; 250 spheres, "
                        "solid fraction 0.35",
                        a));
}
