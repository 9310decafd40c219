#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "core/Error.hpp"
#include "core/Sha256.hpp"
#include "core/Version.hpp"
#include "core/io/H5InputFile.hpp"
#include "core/io/ParticleFrameReader.hpp"
#include "core/io/ParticleFrameWriter.hpp"
#include "tests/core/io/IoTestSupport.hpp"

namespace grainbridge::core::io {
namespace {

using iotest::expectError;
using iotest::sampleParticleFrame;
using iotest::TempDir;

TEST(ParticleFrameSerialization, RoundTripKeepsEveryField) {
  const TempDir dir;
  ParticleFrameWriter writer(dir.path(), {"stage-key-abc"});
  const data::ParticleFrame frame = sampleParticleFrame(1234, 0.0625, 6, 6);
  const auto path = writer.write(frame);
  EXPECT_EQ(path, dir.path() / "frames" / "particles_000001234.h5");

  const data::ParticleFrame back = readParticleFrame(path);
  EXPECT_EQ(back.time, frame.time);
  EXPECT_EQ(back.step, frame.step);
  EXPECT_EQ(back.units, "SI");
  EXPECT_EQ(back.domain, frame.domain);
  EXPECT_EQ(back.id, frame.id);
  EXPECT_EQ(back.species, frame.species);
  EXPECT_EQ(back.radius, frame.radius);
  EXPECT_EQ(back.mass, frame.mass);
  EXPECT_EQ(back.position, frame.position);
  EXPECT_EQ(back.velocity, frame.velocity);
  EXPECT_EQ(back.angularVelocity, frame.angularVelocity);
  EXPECT_EQ(back.externalForce, frame.externalForce);
  EXPECT_EQ(back.contacts, frame.contacts);
  EXPECT_EQ(back.wallContacts, frame.wallContacts);
  EXPECT_EQ(back, frame);  // and nothing else differs
}

TEST(ParticleFrameSerialization, StampCarriesStageKeyAndCodeVersion) {
  const TempDir dir;
  ParticleFrameWriter writer(dir.path(), {"0123456789abcdef"});
  const auto path = writer.write(sampleParticleFrame(1, 0.5, 2, 1));
  const FileStamp stamp = readStamp(path);
  EXPECT_EQ(stamp.stageKey, "0123456789abcdef");
  EXPECT_EQ(stamp.codeVersion, codeVersion().gitSha);
  EXPECT_EQ(stamp.codeDirty, codeVersion().dirty);
  EXPECT_EQ(stamp.formatVersion, kParticleFormatVersion);
}

TEST(ParticleFrameSerialization, EmptyFrameRoundTrips) {
  const TempDir dir;
  ParticleFrameWriter writer(dir.path(), {"k"});
  data::ParticleFrame empty;
  empty.step = 7;
  empty.time = 1.5;
  const auto path = writer.write(empty);
  const data::ParticleFrame back = readParticleFrame(path);
  EXPECT_EQ(back, empty);
  EXPECT_EQ(back.size(), 0U);
  EXPECT_EQ(back.contacts.size(), 0U);
  EXPECT_TRUE(back.domain.walls.empty());
}

TEST(ParticleFrameSerialization, FrameWithoutContactsOrExternalForceRoundTrips) {
  const TempDir dir;
  ParticleFrameWriter writer(dir.path(), {"k"});
  const data::ParticleFrame frame = sampleParticleFrame(3, 0.25, 4, 0, /*withExternalForce=*/false);
  const data::ParticleFrame back = readParticleFrame(writer.write(frame));
  EXPECT_EQ(back, frame);
  EXPECT_TRUE(back.externalForce.empty());
  const ParticleFrameSummary s = readParticleFrameSummary(dir.path() / "frames" / "particles_000000003.h5");
  EXPECT_EQ(s.particles, 4U);
  EXPECT_EQ(s.contacts, 0U);
  EXPECT_FALSE(s.hasExternalForce);
}

TEST(ParticleFrameSerialization, SegmentsRunFromParticleIAlongMinusBranch) {
  const TempDir dir;
  ParticleFrameWriter writer(dir.path(), {"k"});
  const data::ParticleFrame frame = sampleParticleFrame(1, 0.0, 4, 4);
  const H5InputFile f(writer.write(frame));
  const std::vector<Vec3> segments = f.readVec3s("/contacts/segments", {8});
  // Contact 3 pairs the last particle with the first across the periodic x boundary: its
  // segment must stay short (|branch|), not span the box.
  for (std::size_t c = 0; c < 4; ++c) {
    const std::size_t pi = (c % 4);
    EXPECT_EQ(segments[2 * c], frame.position[pi]);
    EXPECT_EQ(segments[2 * c + 1], frame.position[pi] - frame.contacts.branch[c]);
    EXPECT_LT((segments[2 * c] - segments[2 * c + 1]).norm(), 0.5);
  }
  EXPECT_EQ(f.readInt64s("/contacts/segment_connectivity", {4, 2}),
            (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7}));
}

TEST(ParticleFrameSerialization, EqualContentGivesEqualBytes) {
  const TempDir a, b;
  const data::ParticleFrame frame = sampleParticleFrame(42, 0.125, 5, 5);
  const auto first = ParticleFrameWriter(a.path(), {"k"}).write(frame);
  // HDF5 object timestamps have one-second resolution: wait past a tick so they would show.
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  const auto second = ParticleFrameWriter(b.path(), {"k"}).write(frame);
  EXPECT_EQ(sha256File(first), sha256File(second));

  // The same with deflate, and an empty frame.
  const TempDir c, d;
  EXPECT_EQ(sha256File(ParticleFrameWriter(c.path(), {"k"}, 4).write(frame)),
            sha256File(ParticleFrameWriter(d.path(), {"k"}, 4).write(frame)));
  EXPECT_EQ(readParticleFrame(c.path() / "frames" / "particles_000000042.h5"), frame);
  const TempDir e, f;
  data::ParticleFrame empty;
  EXPECT_EQ(sha256File(ParticleFrameWriter(e.path(), {"k"}).write(empty)),
            sha256File(ParticleFrameWriter(f.path(), {"k"}).write(empty)));

  // Different content (or stage key) must give a different hash.
  data::ParticleFrame changed = frame;
  changed.velocity[2].x() += 1e-12;
  const TempDir g, h;
  EXPECT_NE(sha256File(ParticleFrameWriter(g.path(), {"k"}).write(changed)), sha256File(first));
  EXPECT_NE(sha256File(ParticleFrameWriter(h.path(), {"other-key"}).write(frame)), sha256File(first));
}

TEST(ParticleFrameSerialization, RejectsInconsistentFramesAndKeepsEarlierFrames) {
  const TempDir dir;
  ParticleFrameWriter writer(dir.path(), {"k"});
  const auto good = writer.write(sampleParticleFrame(4, 0.0, 3, 2));
  const std::string goodHash = sha256File(good);

  data::ParticleFrame frame = sampleParticleFrame(5, 0.0, 3, 2);
  frame.mass.pop_back();
  expectError([&] { writer.write(frame); }, {"step 5", "'mass'", "2 entries", "expected 3"});

  frame = sampleParticleFrame(5, 0.0, 3, 2);
  frame.contacts.forceTangentialDissipative.pop_back();
  expectError([&] { writer.write(frame); }, {"'forceTangentialDissipative'"});

  frame = sampleParticleFrame(5, 0.0, 3, 2);
  frame.contacts.i[1] = 999;
  expectError([&] { writer.write(frame); }, {"contact 1", "999", "not a particle id"});

  frame = sampleParticleFrame(5, 0.0, 3, 2);
  frame.wallContacts.wall[0] = 2;
  expectError([&] { writer.write(frame); }, {"wall 2", "2 wall(s)"});

  frame = sampleParticleFrame(5, 0.0, 3, 2);
  frame.domain.walls[1].kind = "sphere";
  expectError([&] { writer.write(frame); }, {"'sphere'", "'plane' or 'cylinder'"});

  // Nothing half-written: only the good frame, unchanged, and no temporaries.
  EXPECT_EQ(listParticleFrames(dir.path()), std::vector<std::filesystem::path>{good});
  EXPECT_EQ(sha256File(good), goodHash);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path() / "frames")) ++files;
  EXPECT_EQ(files, 1U);
}

TEST(ParticleFrameSerialization, ListsFramesByStepAndIgnoresOtherFiles) {
  const TempDir dir;
  ParticleFrameWriter writer(dir.path(), {"k"});
  for (const std::int64_t step : {1000000000LL, 20LL, 3LL}) writer.write(sampleParticleFrame(step, 0.1 * step, 2, 1));
  std::filesystem::create_directories(dir.path() / "frames");
  for (const char* other : {"particles_000000005.h5.tmp", "fields_000000001.h5", "particles_x.h5", "notes.txt"}) {
    std::ofstream(dir.path() / "frames" / other) << "x";
  }
  const auto frames = listParticleFrames(dir.path());
  ASSERT_EQ(frames.size(), 3U);
  EXPECT_EQ(frames[0].filename(), "particles_000000003.h5");
  EXPECT_EQ(frames[1].filename(), "particles_000000020.h5");
  EXPECT_EQ(frames[2].filename(), "particles_1000000000.h5");
  EXPECT_TRUE(listParticleFrames(dir.path() / "nowhere").empty());

  // A new writer (restarted run) clears the stray temporary of a killed write.
  const ParticleFrameWriter restarted(dir.path(), {"k"});
  EXPECT_EQ(restarted.frameCount(), 3U);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "frames" / "particles_000000005.h5.tmp"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "frames" / "notes.txt"));
}

}  // namespace
}  // namespace grainbridge::core::io
