// The surface observer's verdict: only frames of a packed bed are judged, and "settled at
// the top" is the earliest judged frame after which the nut never leaves the top.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "core/data/ParticleFrame.hpp"
#include "extract/observe/SurfaceObserver.hpp"
#include "tests/extract/structure/StructureTestFrames.hpp"

namespace grainbridge::extract::observe {
namespace {

// A nut (id 0, radius 1.5) with one grain (id 1, diameter 1) in contact `depth` above its top,
// measured as the grain's top above the nut's top.
core::data::ParticleFrame frame(double time, double depth) {
  core::data::ParticleFrame f;
  f.time = time;
  f.domain.lo = Vec3(-5, -5, 0);
  f.domain.hi = Vec3(5, 5, 50);
  structure::testing::addParticle(f, 0, Vec3(0, 0, 10), 1.5);
  structure::testing::addParticle(f, 1, Vec3(0, 0, 10 + 1.5 + depth - 0.5), 0.5);
  f.wallContacts.particle.push_back(1);  // part of the bed, not in flight
  f.wallContacts.wall.push_back(0);
  f.wallContacts.point.push_back(Vec3::Zero());
  f.wallContacts.forceNormal.push_back(Vec3::UnitX());
  f.wallContacts.forceTangential.push_back(Vec3::Zero());
  return f;
}

// The frame with its whole-domain coordination set as the extract stage would compute it.
void add(SurfaceObserver& observer, core::data::ParticleFrame f, double coordination) {
  coarse::DomainAverages domain;
  domain.coordinationNumber = coordination;
  ObservedFrame observed{f, domain};
  observer.observe(observed);
}

TEST(SurfaceObserver, SettlesAtTheFirstJudgedFrameAfterWhichTheNutStaysAtTheTop) {
  SurfaceObserver tracker({{0}, Vec3::UnitZ(), 1.0, 2.0});
  // (time, gap in diameters, coordination): buried, at the top, buried again, then at the top for
  // good; a loose frame (coordination 0.5) buried in between is not judged.
  add(tracker, frame(1, 5.0), 3.0);
  add(tracker, frame(2, 0.8), 3.0);
  add(tracker, frame(3, 2.0), 3.0);
  add(tracker, frame(4, 0.9), 3.0);
  add(tracker, frame(5, 4.0), 0.5);
  add(tracker, frame(6, 1.0), 3.1);
  const auto s = tracker.summary();
  EXPECT_EQ(s.at("surface_id0_judged_frames"), 5);
  EXPECT_DOUBLE_EQ(s.at("surface_id0_first_at_top_time").get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(s.at("surface_id0_settled_at_top_time").get<double>(), 4.0);
  EXPECT_NEAR(s.at("surface_id0_last_gap_diameters").get<double>(), 1.0, 1e-12);

  std::istringstream csv(tracker.csv());
  std::string line;
  std::getline(csv, line);
  for (int k = 0; k < 5; ++k) std::getline(csv, line);
  EXPECT_EQ(line.substr(line.size() - 3), ",0,") << "the loose frame is written, not judged: " << line;
}

TEST(SurfaceObserver, ANutBuriedAtTheLastJudgedFrameHasNotSettled) {
  SurfaceObserver tracker({{0}, Vec3::UnitZ(), 1.0, 2.0});
  add(tracker, frame(1, 0.5), 3.0);
  add(tracker, frame(2, 3.0), 3.0);
  const auto s = tracker.summary();
  EXPECT_DOUBLE_EQ(s.at("surface_id0_first_at_top_time").get<double>(), 1.0);
  EXPECT_TRUE(s.at("surface_id0_settled_at_top_time").is_null());
}

}  // namespace
}  // namespace grainbridge::extract::observe
