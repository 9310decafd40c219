// A CoarseGrainer reused frame after frame gives exactly the fields of the one-shot coarseGrain
// for every frame: through changes of occupancy (it clears and finalises only the cells frames
// reach), species, shear, drag, grid and kernel. Plus the id lookup behind every contact: dense
// and sparse ids, a missing id and a repeated one named.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "extract/coarse/CoarseGrain.hpp"
#include "extract/coarse/ParticleContacts.hpp"
#include "tests/extract/coarse/CoarseTestFrames.hpp"

using namespace grainbridge;
using namespace grainbridge::extract::coarse;
using namespace grainbridge::extract::coarse::testing;

namespace {

struct FrameSpec {
  double zLo = 0.0, zHi = 1.0;  // particles between these fractions of the box height
  int species = 1;
  bool sheared = false, drag = false;
  std::int64_t firstId = 0, idStride = 1;
};

// Particles at random in part of a 6 x 5 x 8 box (periodic in x and y, walls in z), contacts
// between random pairs with branches of about a diameter, and a few wall contacts.
core::data::ParticleFrame randomFrame(const FrameSpec& spec, std::uint64_t seed) {
  core::data::ParticleFrame f;
  f.domain.lo = Vec3(0, 0, 0);
  f.domain.hi = Vec3(6, 5, 8);
  f.domain.periodic = {true, true, false};
  if (spec.sheared) {
    f.domain.leesEdwardsOffset = 1.7;
    f.domain.leesEdwardsShearRate = 0.3;
  }
  f.domain.walls.push_back({"plane", Vec3(0, 0, 0), Vec3(0, 0, 1), 0.0, Vec3::Zero()});
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 300;
  std::vector<std::int64_t> ids;
  for (int i = 0; i < n; ++i) {
    const Vec3 x(6 * u(rng), 5 * u(rng), 8 * (spec.zLo + (spec.zHi - spec.zLo) * u(rng)));
    const std::int64_t id = spec.firstId + spec.idStride * ((i * 7) % n);  // not in frame order
    addParticle(f, id, static_cast<std::int32_t>(2 + i % spec.species), 0.4 + 0.1 * u(rng), 1.0 + u(rng), x,
                Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
    if (spec.drag) f.externalForce.push_back(Vec3(0, 0, u(rng)));
    ids.push_back(id);
  }
  for (int k = 0; k < 500; ++k) {
    const auto i = static_cast<std::size_t>(u(rng) * n), j = (i + 1 + static_cast<std::size_t>(u(rng) * (n - 1))) % n;
    addContact(f, ids[i], ids[j], Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5) * 1.2, Vec3(u(rng), u(rng), u(rng)),
               Vec3(u(rng) - 0.5, 0, 0));
  }
  for (int k = 0; k < 10; ++k) {
    const auto i = static_cast<std::size_t>(u(rng) * n);
    auto& w = f.wallContacts;
    w.particle.push_back(ids[i]);
    w.wall.push_back(0);
    w.point.push_back(Vec3(f.position[i][0], f.position[i][1], 0.0));
    w.forceNormal.push_back(Vec3(0, 0, 2 * u(rng)));
    w.forceTangential.push_back(Vec3::Zero());
  }
  return f;
}

void expectSameFields(const CoarseFields& got, const CoarseFields& want, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(got.grid, want.grid);
  EXPECT_EQ(got.kernel, want.kernel);
  EXPECT_EQ(got.solidFraction, want.solidFraction);
  EXPECT_EQ(got.density, want.density);
  EXPECT_EQ(got.velocity, want.velocity);
  EXPECT_EQ(got.granularTemperature, want.granularTemperature);
  EXPECT_EQ(got.kineticStress, want.kineticStress);
  EXPECT_EQ(got.contactStress, want.contactStress);
  EXPECT_EQ(got.stress, want.stress);
  EXPECT_EQ(got.pressure, want.pressure);
  EXPECT_EQ(got.shearStress, want.shearStress);
  EXPECT_EQ(got.deviatoricStress, want.deviatoricStress);
  EXPECT_EQ(got.particleCount, want.particleCount);
  EXPECT_EQ(got.coordinationNumber, want.coordinationNumber);
  EXPECT_EQ(got.multiContactRatio, want.multiContactRatio);
  EXPECT_EQ(got.contactForce, want.contactForce);
  EXPECT_EQ(got.dragForce, want.dragForce);
  EXPECT_EQ(got.contactToDragRatio, want.contactToDragRatio);
  ASSERT_EQ(got.species.size(), want.species.size());
  for (std::size_t k = 0; k < got.species.size(); ++k) {
    EXPECT_EQ(got.species[k].species, want.species[k].species);
    EXPECT_EQ(got.species[k].solidFraction, want.species[k].solidFraction);
    EXPECT_EQ(got.species[k].density, want.species[k].density);
    EXPECT_EQ(got.species[k].velocity, want.species[k].velocity);
    EXPECT_EQ(got.species[k].granularTemperature, want.species[k].granularTemperature);
  }
}

std::string message(const auto& call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(CoarseGrainer, ReusedFrameAfterFrameGivesTheOneShotFields) {
  const auto box = randomFrame({}, 1).domain;
  const core::grid::CellGrid grid = core::grid::CellGrid::overDomain(box, {6, 5, 8});
  const core::grid::CellGrid fine = core::grid::CellGrid::overDomain(box, {12, 10, 16});
  // Same cell count as grid, other cells: a sub-region, not periodic.
  const core::grid::CellGrid region(Vec3(1, 1, 1), Vec3(5, 4, 7), {6, 5, 8});
  struct Step {
    FrameSpec frame;
    const core::grid::CellGrid* grid;
    CoarseGrainingKernel kernel;
  };
  const std::vector<Step> steps{
      {{0.0, 0.4}, &grid, CoarseGrainingKernel::bin()},                          // a bed
      {{0.0, 0.6}, &grid, CoarseGrainingKernel::bin()},                          // it grows
      {{0.5, 1.0}, &grid, CoarseGrainingKernel::bin()},                          // moves up
      {{0.0, 0.3}, &grid, CoarseGrainingKernel::bin()},                          // and down
      {{0.0, 1.0, 2, false, true, 100, 3}, &grid, CoarseGrainingKernel::bin()},  // species, drag, sparse ids
      {{0.0, 1.0, 2, true, true}, &grid, CoarseGrainingKernel::bin()},           // sheared
      {{0.2, 0.5, 1, true}, &grid, CoarseGrainingKernel::bin()},
      {{0.0, 0.5}, &region, CoarseGrainingKernel::bin()},
      {{0.0, 0.5}, &fine, CoarseGrainingKernel::overlap()},
      {{0.3, 0.9, 3}, &fine, CoarseGrainingKernel::lucy(0.6)},
      {{0.0, 0.4}, &grid, CoarseGrainingKernel::bin()},
  };
  CoarseGrainer grainer;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const auto frame = randomFrame(steps[s].frame, 100 + s);
    const CoarseFields& reused = grainer(frame, *steps[s].grid, steps[s].kernel);
    expectSameFields(reused, coarseGrain(frame, *steps[s].grid, steps[s].kernel), "step " + std::to_string(s));
  }
  // A failed call leaves nothing behind for the next.
  auto broken = randomFrame({0.0, 1.0}, 7);
  broken.contacts.j[3] = 99999;
  EXPECT_NE(message([&] { grainer(broken, grid, CoarseGrainingKernel::bin()); }).find("particle id 99999"),
            std::string::npos);
  EXPECT_NE(message([&] { grainer(randomFrame({}, 8), fine, CoarseGrainingKernel::lucy(0.1)); }).find("too narrow"),
            std::string::npos);
  const auto frame = randomFrame({0.1, 0.2}, 9);
  expectSameFields(grainer(frame, grid, CoarseGrainingKernel::bin()),
                   coarseGrain(frame, grid, CoarseGrainingKernel::bin()), "after errors");
  const CoarseFields released = grainer.release();
  expectSameFields(released, coarseGrain(frame, grid, CoarseGrainingKernel::bin()), "released");
}

TEST(ParticleIndex, DenseAndSparseIdsMissingAndRepeatedOnes) {
  for (const std::int64_t stride : {std::int64_t{1}, std::int64_t{3}, std::int64_t{1} << 40}) {
    SCOPED_TRACE(stride);
    core::data::ParticleFrame f;
    const std::vector<std::int64_t> ids{7, 3, 9, 4, 5};
    for (const std::int64_t id : ids) addParticle(f, -50 + stride * id, 0, 0.5, 1.0, Vec3::Zero(), Vec3::Zero());
    const ParticleIndex index(f);
    for (std::size_t i = 0; i < ids.size(); ++i) EXPECT_EQ(index.find(-50 + stride * ids[i]), i);
    EXPECT_EQ(index.find(-50 + stride * 6), ParticleIndex::npos);
    EXPECT_EQ(index.find(-50 + stride * 100), ParticleIndex::npos);
    EXPECT_EQ(index.find(-51 - stride), ParticleIndex::npos);
    EXPECT_NE(
        message([&] {
          (void)index.at(-50 + stride * 8, "contact", 12);
        }).find("contact 12 refers to particle id " + std::to_string(-50 + stride * 8) + ", which is not in the frame"),
        std::string::npos);
    // The first id, in frame order, that was seen before.
    addParticle(f, -50 + stride * 5, 0, 0.5, 1.0, Vec3::Zero(), Vec3::Zero());
    addParticle(f, -50 + stride * 3, 0, 0.5, 1.0, Vec3::Zero(), Vec3::Zero());
    EXPECT_NE(message([&] {
                ParticleIndex{f};
              }).find("particle id " + std::to_string(-50 + stride * 5) + " appears more than once"),
              std::string::npos);
  }
}

TEST(ParticleContacts, FrameIndicesOfEachContactsParticles) {
  const auto f = randomFrame({0.0, 1.0, 1, false, false, 1000, 7}, 3);
  const ParticleIndex index(f);
  const ParticleContacts contacts = particleContacts(f, index);
  ASSERT_EQ(contacts.first.size(), f.contacts.size());
  for (std::size_t k = 0; k < f.contacts.size(); ++k) {
    EXPECT_EQ(f.id[contacts.first[k]], f.contacts.i[k]);
    EXPECT_EQ(f.id[contacts.second[k]], f.contacts.j[k]);
  }
  ASSERT_EQ(contacts.wallParticle.size(), f.wallContacts.size());
  for (std::size_t k = 0; k < f.wallContacts.size(); ++k) {
    EXPECT_EQ(f.id[contacts.wallParticle[k]], f.wallContacts.particle[k]);
  }
}
