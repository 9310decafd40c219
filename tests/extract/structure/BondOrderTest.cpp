// Bond-orientational order (extract/structure/BondOrder, issue 61): a perfect fcc lattice has
// q6 = 0.57452 (Steinhardt, Nelson and Ronchetti 1983, Table I) and every particle crystalline,
// also with thermal-like displacements of 4 % of a diameter and across periodic images; points
// placed at random at the same density have a low q6 and almost no crystalline particles.
#include "extract/structure/BondOrder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/Error.hpp"

using namespace grainbridge;
using namespace grainbridge::extract::structure;

namespace {

// n^3 fcc unit cells of nearest-neighbour distance 1 (cube edge sqrt 2), periodic.
struct Lattice {
  core::data::Domain domain;
  std::vector<Vec3> positions;
};

Lattice fcc(int n, double jitter, std::uint64_t seed) {
  const double a = std::sqrt(2.0);
  Lattice l;
  l.domain.lo = Vec3::Zero();
  l.domain.hi = Vec3::Constant(n * a);
  l.domain.periodic = {true, true, true};
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, jitter);
  const std::array<Vec3, 4> basis{Vec3(0, 0, 0), Vec3(0.5, 0.5, 0), Vec3(0.5, 0, 0.5), Vec3(0, 0.5, 0.5)};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const auto& b : basis) {
          const Vec3 p = (Vec3(i, j, k) + b) * a;
          l.positions.push_back(jitter > 0.0 ? Vec3(p + Vec3(g(rng), g(rng), g(rng))) : p);
        }
  return l;
}

}  // namespace

TEST(BondOrder, AnFccLatticeIsCrystallineAndARandomGasIsNot) {
  const auto perfect = fcc(4, 0.0, 1);
  const auto order = bondOrder(perfect.domain, perfect.positions, 1.3);
  EXPECT_NEAR(order.meanQ6, 0.57452, 1e-4);
  EXPECT_DOUBLE_EQ(order.crystallineShare, 1.0);

  const auto shaken = fcc(4, 0.04, 2);
  const auto shakenOrder = bondOrder(shaken.domain, shaken.positions, 1.3);
  EXPECT_GT(shakenOrder.crystallineShare, 0.95);
  EXPECT_GT(shakenOrder.meanQ6, 0.5);

  // The same number of points at random in the same box.
  auto gas = perfect;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, gas.domain.hi[0]);
  for (auto& p : gas.positions) p = Vec3(u(rng), u(rng), u(rng));
  const auto gasOrder = bondOrder(gas.domain, gas.positions, 1.3);
  std::printf("q6: fcc %.5f, shaken %.3f, gas %.3f; crystalline: %.3f, %.3f, %.3f\n", order.meanQ6, shakenOrder.meanQ6,
              gasOrder.meanQ6, order.crystallineShare, shakenOrder.crystallineShare, gasOrder.crystallineShare);
  EXPECT_LT(gasOrder.crystallineShare, 0.05);
  EXPECT_THROW((void)bondOrder(gas.domain, gas.positions, 0.0), Error);
}

// A Lees-Edwards box whose image above is shifted by half a cube edge along x, with a height of
// 4.5 cube edges: (a/2, 4.5 a, 0) is a lattice vector, so the lattice is whole across the y
// boundary only when the neighbours there are found through the shifted image.
TEST(BondOrder, NeighboursAreFoundThroughTheLeesEdwardsImage) {
  const double a = std::sqrt(2.0);
  core::data::Domain domain;
  domain.hi = Vec3(4 * a, 4.5 * a, 4 * a);
  domain.periodic = {true, true, true};
  domain.leesEdwardsOffset = 0.5 * a;
  const std::array<Vec3, 4> basis{Vec3(0, 0, 0), Vec3(0.5, 0.5, 0), Vec3(0.5, 0, 0.5), Vec3(0, 0.5, 0.5)};
  std::vector<Vec3> positions;
  for (int i = -1; i <= 5; ++i)
    for (int j = -1; j <= 5; ++j)
      for (int k = -1; k <= 5; ++k)
        for (const auto& b : basis) {
          const Vec3 p = (Vec3(i, j, k) + b) * a;
          if ((p.array() >= -1e-9).all() && (p.array() < domain.hi.array() - 1e-9).all()) positions.push_back(p);
        }
  ASSERT_EQ(positions.size(), 4u * 4u * 4u * 4u + 2u * 4u * 4u);  // 4.5 cells along y
  const auto order = bondOrder(domain, positions, 1.3);
  EXPECT_NEAR(order.meanQ6, 0.57452, 1e-4);
  EXPECT_DOUBLE_EQ(order.crystallineShare, 1.0);
  // The same points without the shift are mismatched at the boundary: the particles there see
  // another neighbour shell (the solid-bond criterion still counts most of them crystalline).
  domain.leesEdwardsOffset = 0.0;
  const auto unshifted = bondOrder(domain, positions, 1.3);
  std::printf("without the shift: q6 %.4f, crystalline %.3f\n", unshifted.meanQ6, unshifted.crystallineShare);
  EXPECT_GT(std::abs(unshifted.meanQ6 - 0.57452), 0.01);
}
