// The minimum image of a frame's box: periodic wrapping, open axes left alone, and the engine's
// Lees-Edwards convention (the image above the box in y sits at x + offset).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/Error.hpp"
#include "extract/geometry/PeriodicBox.hpp"

namespace grainbridge::extract::geometry {
namespace {

using core::data::Domain;

Domain box(const Vec3& lo, const Vec3& hi, std::array<bool, 3> periodic, double offset = 0.0) {
  Domain d;
  d.lo = lo;
  d.hi = hi;
  d.periodic = periodic;
  d.leesEdwardsOffset = offset;
  return d;
}

TEST(PeriodicBox, PeriodicAxesWrapAndOpenAxesDoNot) {
  const PeriodicBox b(box(Vec3::Zero(), Vec3(10, 10, 10), {true, true, false}));
  const Vec3 p(0.5, 9.5, 5.0), q(9.5, 0.5, 5.0);
  EXPECT_TRUE(b.minimumImage(p - q).isApprox(Vec3(1, -1, 0)));
  // z is open: a plain difference, however long.
  EXPECT_TRUE(b.minimumImage(Vec3(0, 0, 9.5) - Vec3(0, 0, 0.5)).isApprox(Vec3(0, 0, 9)));
  EXPECT_EQ(b.maxUniqueDistance(), 5.0);
  EXPECT_EQ(PeriodicBox(Domain{}).maxUniqueDistance(), std::numeric_limits<double>::infinity());
}

TEST(PeriodicBox, LeesEdwardsImageAboveIsShiftedByTheOffset) {
  // Offset 2: q's image above the box is at (9.5 + 2, 10.5) = (1.5, 10.5) after the x wrap, so
  // p - image = (-1, -1).
  const PeriodicBox b(box(Vec3::Zero(), Vec3(10, 10, 10), {true, true, false}, 2.0));
  const Vec3 p(0.5, 9.5, 5.0), q(9.5, 0.5, 5.0);
  EXPECT_TRUE(b.minimumImage(p - q).isApprox(Vec3(-1, -1, 0)));
  EXPECT_TRUE(b.minimumImage(q - p).isApprox(Vec3(1, 1, 0)));
  // The engine puts the image above the box (y + L_y) at x + offset (Simulation::buildGhosts).
  const PeriodicBox e(box(Vec3::Zero(), Vec3(10, 8, 6), {true, true, true}, 3.0));
  const Vec3 top(4.0, 7.8, 1.0), bottom(1.2, 0.1, 1.0);
  const Vec3 imageAbove = bottom + Vec3(3.0, 8.0, 0.0);
  EXPECT_TRUE(e.minimumImage(top - bottom).isApprox(top - imageAbove, 1e-12));
  EXPECT_TRUE(e.minimumImage(bottom - top).isApprox(imageAbove - top, 1e-12));
}

TEST(PeriodicBox, MinimumImageIsTheRoundingDefinitionBitForBit) {
  // The definition with std::round: MST ties rely on every caller getting these exact bits.
  const Domain d = box(Vec3(-1, 2, 0.5), Vec3(5.5, 7, 4.25), {true, true, true}, 2.75);
  const PeriodicBox b(d);
  const Vec3 L = d.hi - d.lo;
  const auto reference = [&](Vec3 v) {
    if (std::abs(v[1]) > 0.5 * L[1]) {
      const double n = std::round(v[1] / L[1]);
      v[1] -= n * L[1];
      v[0] -= n * d.leesEdwardsOffset;
    }
    for (int a : {0, 2}) {
      if (std::abs(v[a]) > 0.5 * L[a]) v[a] -= std::round(v[a] / L[a]) * L[a];
    }
    return v;
  };
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-40.0, 40.0);
  std::vector<Vec3> ds{Vec3(3.25, 2.5, 1.875),    Vec3(-3.25, -2.5, -1.875),
                       Vec3(9.75, 7.5, 5.625),    Vec3(-9.75, -7.5, -5.625),
                       Vec3(16.25, -12.5, 9.375), Vec3(1e17, -1e17, 3e16)};  // odd halves of edges, huge
  for (int k = 0; k < 10000; ++k) ds.emplace_back(u(rng), u(rng), u(rng));
  for (const Vec3& v : ds) {
    const Vec3 got = b.minimumImage(v), want = reference(v);
    for (int a = 0; a < 3; ++a) ASSERT_EQ(got[a], want[a]) << v.transpose();
  }
}

TEST(PeriodicBox, WrapMovesAPointAboveTheBoxDownAndBackByTheOffset) {
  const PeriodicBox b(box(Vec3::Zero(), Vec3(10, 10, 10), {true, true, false}, 2.0));
  EXPECT_TRUE(b.wrap(Vec3(1.0, 10.5, 3.0)).isApprox(Vec3(9.0, 0.5, 3.0)));
  EXPECT_TRUE(b.wrap(Vec3(1.0, 0.5, 13.0)).isApprox(Vec3(1.0, 0.5, 13.0)));  // z is open
  // The half-open box holds even where round-off would land on hi.
  const Vec3 w = b.wrap(Vec3(-1e-17, 5.0, 0.0));
  EXPECT_GE(w[0], 0.0);
  EXPECT_LT(w[0], 10.0);
}

TEST(PeriodicBox, RejectsInconsistentDomains) {
  EXPECT_THROW(PeriodicBox{box(Vec3::Zero(), Vec3::Zero(), {true, false, false})}, Error);  // zero length
  EXPECT_THROW(PeriodicBox{box(Vec3::Zero(), Vec3(1, std::nan(""), 1), {false, true, false})}, Error);
  // Lees-Edwards needs x and y periodic.
  EXPECT_THROW(PeriodicBox{box(Vec3::Zero(), Vec3(1, 1, 1), {false, true, true}, 0.2)}, Error);
  EXPECT_THROW(PeriodicBox{box(Vec3::Zero(), Vec3(1, 1, 1), {true, false, false}, 0.2)}, Error);
  Domain sheared = box(Vec3::Zero(), Vec3(1, 1, 1), {true, false, true});
  sheared.leesEdwardsShearRate = 0.1;
  EXPECT_THROW(PeriodicBox{sheared}, Error);
}

}  // namespace
}  // namespace grainbridge::extract::geometry
