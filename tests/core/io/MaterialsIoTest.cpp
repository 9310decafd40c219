// The materials contract of particle frames (issue 14, item 1): what an engine writes beside
// each frame comes back exactly, a frame without it reads as empty, and a frame whose materials
// contradict its particles or walls is refused on write.
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "core/io/ParticleFrameReader.hpp"
#include "core/io/ParticleFrameWriter.hpp"
#include "tests/core/io/IoTestSupport.hpp"

namespace grainbridge::core::io {
namespace {

using iotest::sampleParticleFrame;
using iotest::TempDir;

// Two species (the sample frame alternates 0, 1), three pairs, one wall entry per species on
// each of the sample's two walls, gravity along -z.
data::Materials twoSpeciesMaterials() {
  data::Materials m;
  m.species = {{"small", 0.002, 2500.0}, {"large", 0.004, 1200.0}};
  m.pairs = {{0, 0, -1, 0.9, 0.0, 1e5, 2e4}, {0, 1, -1, 0.8, 0.5, 1e5, 2e4}, {1, 1, -1, 0.7, 0.25, 2e5, 4e4}};
  for (std::int32_t w = 0; w < 2; ++w) {
    for (std::int32_t s = 0; s < 2; ++s) m.walls.push_back({s, s, w, 0.6, 0.1 * (w + 1), 3e5, 6e4});
  }
  m.gravity = Vec3(0.0, 0.0, -9.81);
  return m;
}

TEST(MaterialsIo, RoundTripKeepsEveryCoefficient) {
  const TempDir dir;
  auto frame = sampleParticleFrame(10, 0.5, 6, 6);
  frame.materials = twoSpeciesMaterials();
  const auto back = readParticleFrame(ParticleFrameWriter(dir.path(), {"k"}).write(frame));
  EXPECT_EQ(back.materials, frame.materials);
  ASSERT_TRUE(back.materials.pair(1, 0).has_value());
  EXPECT_EQ(back.materials.pair(1, 0)->restitution, 0.8);
  EXPECT_EQ(back.materials.up(), Vec3(0.0, 0.0, 1.0));
}

TEST(MaterialsIo, FrameWithoutMaterialsReadsEmpty) {
  const TempDir dir;
  const auto back = readParticleFrame(ParticleFrameWriter(dir.path(), {"k"}).write(sampleParticleFrame(1, 0.0, 4, 2)));
  EXPECT_TRUE(back.materials.empty());
  EXPECT_EQ(back.materials.up(), Vec3::UnitZ());
}

TEST(MaterialsIo, RefusesMaterialsThatContradictTheFrame) {
  const TempDir dir;
  ParticleFrameWriter writer(dir.path(), {"k"});
  auto frame = sampleParticleFrame(1, 0.0, 6, 6);
  frame.materials = twoSpeciesMaterials();
  frame.materials.species.pop_back();  // particles of species 1 have no material now
  frame.materials.pairs.pop_back();
  frame.materials.pairs.pop_back();
  frame.materials.walls.clear();
  EXPECT_THROW(writer.write(frame), Error);
  frame.materials = twoSpeciesMaterials();
  frame.materials.walls.push_back({0, 0, 7, 0.5, 0.0, 1.0, 1.0});  // no wall 7
  EXPECT_THROW(writer.write(frame), Error);
  frame.materials = twoSpeciesMaterials();
  frame.materials.pairs[1].restitution = 1.5;
  EXPECT_THROW(writer.write(frame), Error);
}

}  // namespace
}  // namespace grainbridge::core::io
