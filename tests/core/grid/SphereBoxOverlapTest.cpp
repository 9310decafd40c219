// Closed-form sphere-box overlap volume against independent results: the whole sphere, the
// octant, the spherical cap (one plane), the spherical segment (two parallel planes), a box
// inside the sphere, and Monte Carlo for random boxes cutting the sphere at a corner.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/grid/SphereBoxOverlap.hpp"

using namespace grainbridge;
using namespace grainbridge::core::grid;

namespace {
double sphereVolume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }
// Cap of height h = r - t cut off by a plane at distance t from the centre.
double cap(double r, double t) { return M_PI * (r - t) * (r - t) * (2.0 * r + t) / 3.0; }
}  // namespace

TEST(SphereBoxOverlap, WholeSphereAndOctant) {
  const Vec3 c(0.3, -0.2, 1.1);
  const double r = 0.7;
  EXPECT_NEAR(sphereBoxOverlapVolume(c, r, c - Vec3::Constant(2), c + Vec3::Constant(2)), sphereVolume(r), 1e-15);
  EXPECT_NEAR(sphereBoxOverlapVolume(c, r, c, c + Vec3::Constant(1)), sphereVolume(r) / 8, 1e-15);
  EXPECT_NEAR(sphereBoxOverlapVolume(c, r, c - Vec3::Constant(1), c), sphereVolume(r) / 8, 1e-15);
  EXPECT_EQ(sphereBoxOverlapVolume(c, r, c + Vec3(0.8, 0, 0), c + Vec3(2, 1, 1)), 0.0);
  // A box inside the sphere is its own volume.
  EXPECT_NEAR(sphereBoxOverlapVolume(c, r, c - Vec3::Constant(0.1), c + Vec3(0.2, 0.1, 0.3)), 0.3 * 0.2 * 0.4, 1e-15);
}

TEST(SphereBoxOverlap, HalfSpaceCutIsTheCapFormula) {
  const Vec3 c(1.0, 2.0, 3.0);
  const double r = 0.5;
  const double big = 10.0;
  for (double t : {-0.49, -0.3, -0.1, 0.0, 0.05, 0.25, 0.4999}) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int side : {+1, -1}) {
        // Keep {side * (x_axis - c_axis) > t}: the cap beyond the plane.
        Vec3 lo = c - Vec3::Constant(big), hi = c + Vec3::Constant(big);
        (side > 0 ? lo : hi)[axis] = c[axis] + side * t;
        const double expected = cap(r, t);
        EXPECT_NEAR(sphereBoxOverlapVolume(c, r, lo, hi), expected, 1e-14 * sphereVolume(r))
            << "axis " << axis << " side " << side << " t " << t;
      }
    }
  }
}

TEST(SphereBoxOverlap, SlabBetweenTwoPlanesIsTheSphericalSegment) {
  const Vec3 c = Vec3::Zero();
  const double r = 1.3;
  const double t0 = -0.4, t1 = 0.9;
  const double expected = cap(r, t0) - cap(r, t1);
  EXPECT_NEAR(sphereBoxOverlapVolume(c, r, Vec3(-5, -5, t0), Vec3(5, 5, t1)), expected, 1e-14);
}

TEST(SphereBoxOverlap, CornerRegionFromTheUnitBallPieces) {
  // Symmetric pieces: the quarter and octant of the ball and a cut octant, checked by symmetry.
  EXPECT_NEAR(unitBallCornerVolume(0, 0, 0), M_PI / 6, 1e-15);
  EXPECT_NEAR(unitBallCornerVolume(-1, 0, 0), M_PI / 3, 1e-15);
  EXPECT_NEAR(unitBallCornerVolume(-2, -2, -2), 4 * M_PI / 3, 1e-14);
  EXPECT_NEAR(unitBallCornerVolume(0.2, 0.3, 0.4), unitBallCornerVolume(0.4, 0.2, 0.3), 1e-15);
  EXPECT_NEAR(unitBallCornerVolume(0.3, 0.3, 0.3) + unitBallCornerVolume(-0.3, 0.3, 0.3),
              unitBallCornerVolume(-1, 0.3, 0.3), 1e-15);
  EXPECT_EQ(unitBallCornerVolume(0.6, 0.6, 0.6), 0.0);  // corner outside the ball
}

TEST(SphereBoxOverlap, RandomCornerCasesAgreeWithMonteCarlo) {
  // Boxes with a corner inside the sphere: the hardest case (three planes cut the sphere).
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Vec3 c(0.1, 0.2, -0.3);
  const double r = 1.0;
  const int samples = 400000;
  for (int trial = 0; trial < 4; ++trial) {
    const Vec3 lo = c + Vec3(u(rng), u(rng), u(rng));
    const Vec3 hi = lo + Vec3::Constant(2.0);
    const double exact = sphereBoxOverlapVolume(c, r, lo, hi);
    int inside = 0;
    for (int s = 0; s < samples; ++s) {
      const Vec3 p = c + r * Vec3(unit(rng), unit(rng), unit(rng));
      if ((p - c).squaredNorm() <= r * r && (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all()) {
        ++inside;
      }
    }
    const double cube = 8.0 * r * r * r;
    const double fraction = static_cast<double>(inside) / samples;
    const double mc = cube * fraction;
    const double sigma = cube * std::sqrt(fraction * (1 - fraction) / samples);
    EXPECT_NEAR(exact, mc, 4.0 * sigma) << "trial " << trial << " exact " << exact << " MC " << mc;
  }
}
