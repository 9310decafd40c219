// Contact statistics by particle centre (Figs. 7.5-7.7, 7.11): coordination counts
// particle-particle contacts only, the multi-contact ratio is particles with N_c >= 2 over those
// with N_c >= 1, contact and drag forces are the magnitudes of their sums over a cell's particles
// (their ratio -1 where there is no drag); plus kernel names and errors naming the problem.
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "extract/coarse/CoarseGrain.hpp"
#include "extract/coarse/DomainAverages.hpp"
#include "tests/extract/coarse/CoarseTestFrames.hpp"

using namespace grainbridge;
using namespace grainbridge::extract::coarse;
using namespace grainbridge::extract::coarse::testing;

namespace {
// Cell 0 (x < 5): a chain 0-1-2 and a free particle 3; cell 1: particle 4 against a wall only.
core::data::ParticleFrame chainFrame() {
  core::data::ParticleFrame f;
  f.domain.lo = Vec3::Zero();
  f.domain.hi = Vec3(10, 2, 2);
  f.domain.walls.push_back({"plane", Vec3(10, 0, 0), Vec3(-1, 0, 0), 0.0, Vec3::Zero()});
  addParticle(f, 10, 0, 0.5, 1.0, Vec3(1.0, 1, 1), Vec3::Zero());
  addParticle(f, 11, 0, 0.5, 1.0, Vec3(2.0, 1, 1), Vec3::Zero());
  addParticle(f, 12, 0, 0.5, 1.0, Vec3(3.0, 1, 1), Vec3::Zero());
  addParticle(f, 13, 0, 0.5, 1.0, Vec3(4.2, 1, 1), Vec3::Zero());
  addParticle(f, 14, 0, 0.5, 1.0, Vec3(9.5, 1, 1), Vec3::Zero());
  addContact(f, 10, 11, Vec3(-1, 0, 0), Vec3(-2, 0, 0));
  addContact(f, 11, 12, Vec3(-1, 0, 0), Vec3(-3, 0, 0));
  auto& w = f.wallContacts;
  w.particle.push_back(14);
  w.wall.push_back(0);
  w.point.push_back(Vec3(10, 1, 1));
  w.forceNormal.push_back(Vec3(-5, 0, 0));
  w.forceTangential.push_back(Vec3::Zero());
  f.externalForce = {Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  return f;
}
}  // namespace

TEST(ContactStatistics, CoordinationMultiContactAndForcesByCell) {
  const auto f = chainFrame();
  const core::grid::CellGrid grid(f.domain.lo, f.domain.hi, {2, 1, 1});
  const auto cg = coarseGrain(f, grid, CoarseGrainingKernel::bin());
  EXPECT_EQ(cg.particleCount[0], 4.0);
  EXPECT_DOUBLE_EQ(cg.coordinationNumber[0], (1 + 2 + 1 + 0) / 4.0);
  EXPECT_DOUBLE_EQ(cg.multiContactRatio[0], 1.0 / 3.0);
  EXPECT_EQ(cg.coordinationNumber[1], 0.0);  // the wall contact is not counted
  EXPECT_EQ(cg.multiContactRatio[1], 0.0);
  // Internal forces cancel in a cell's sum: on 10: -2; on 11: +2 - 3; on 12: +3 -> sum 0.
  EXPECT_NEAR(cg.contactForce[0], 0.0, 1e-15);
  EXPECT_NEAR(cg.contactForce[1], 5.0, 1e-15);
  EXPECT_NEAR(cg.dragForce[0], 2.0, 1e-15);
  EXPECT_EQ(cg.contactToDragRatio[1], -1.0);
  const auto avg = averageWholeDomain(f);
  EXPECT_DOUBLE_EQ(avg.coordinationNumber, 2.0 * 2 / 5);
  EXPECT_DOUBLE_EQ(avg.multiContactRatio, 1.0 / 3.0);
  // Wall contact: (r_i - point) F = (-0.5)(-5) in xx over the box volume 40.
  EXPECT_NEAR(avg.contactStress(0, 0), (1 * 2 + 1 * 3 + 0.5 * 5) / 40.0, 1e-15);
}

TEST(ContactStatistics, KernelNamesAndErrorsNameTheProblem) {
  EXPECT_EQ(CoarseGrainingKernel::fromName("lucy", 0.5), CoarseGrainingKernel::lucy(0.5));
  EXPECT_EQ(CoarseGrainingKernel::fromName("overlap").name(), "overlap");
  const auto message = [](auto&& call) {
    try {
      call();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([] { CoarseGrainingKernel::fromName("tophat"); }).find("unknown kernel 'tophat'"),
            std::string::npos);
  const auto f = chainFrame();
  const core::grid::CellGrid grid(f.domain.lo, f.domain.hi, {2, 1, 1});
  EXPECT_NE(message([&] {
              coarseGrain(f, grid, CoarseGrainingKernel::gaussian(0.0));
            }).find("kernel width 0 must be positive"),
            std::string::npos);
  EXPECT_NE(message([&] { coarseGrain(f, grid, CoarseGrainingKernel::lucy(0.2)); }).find("too narrow"),
            std::string::npos);
  const core::grid::CellGrid periodic(f.domain.lo, f.domain.hi, {2, 1, 1}, {true, false, false});
  EXPECT_NE(message([&] { coarseGrain(f, periodic, CoarseGrainingKernel::bin()); }).find("periodic in x"),
            std::string::npos);
  auto broken = f;
  broken.contacts.j[1] = 99;
  EXPECT_NE(message([&] { coarseGrain(broken, grid, CoarseGrainingKernel::bin()); }).find("particle id 99"),
            std::string::npos);
}
