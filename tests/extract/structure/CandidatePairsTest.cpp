// The MST candidate search: the cell list finds exactly the pairs an all-pairs loop finds, with
// the same lengths, in open, periodic, mixed and Lees-Edwards boxes, for particles stored
// outside the box and for cutoffs reaching past half the box.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "core/Error.hpp"
#include "extract/structure/CandidatePairs.hpp"
#include "extract/structure/PeriodicBox.hpp"

namespace grainbridge::extract::structure {
namespace {

using Found = std::tuple<std::uint32_t, std::uint32_t, double>;

std::vector<Found> sorted(const std::vector<CandidatePair>& pairs) {
  std::vector<Found> out;
  for (const CandidatePair& p : pairs) out.emplace_back(p.a, p.b, p.length);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Found> allPairsWithin(const std::vector<Vec3>& x, const PeriodicBox& box, double cutoff) {
  std::vector<Found> out;
  for (std::uint32_t a = 0; a < x.size(); ++a) {
    for (std::uint32_t b = a + 1; b < x.size(); ++b) {
      const double length = box.minimumImage(x[a] - x[b]).norm();
      if (length <= cutoff) out.emplace_back(a, b, length);
    }
  }
  return out;
}

TEST(CandidatePairs, MatchAllPairsInEveryKindOfBox) {
  struct Case {
    const char* name;
    std::array<bool, 3> periodic;
    double leesEdwardsOffset;
    double cutoff;
  };
  const std::vector<Case> cases{
      {"open", {false, false, false}, 0.0, 1.3},
      {"periodic", {true, true, true}, 0.0, 1.3},
      {"periodic x only", {true, false, false}, 0.0, 2.1},
      {"Lees-Edwards", {true, true, true}, 2.35, 1.3},
      {"Lees-Edwards, offset beyond the box", {true, true, true}, 7.9, 1.1},
      {"periodic, cutoff past half the box", {true, true, true}, 0.0, 3.5},
      {"Lees-Edwards, cutoff past half the box", {true, true, true}, 1.4, 3.5},
  };
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> uniform(-0.1, 1.1);  // some particles outside the box
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    core::data::Domain domain;
    domain.lo = Vec3(-2, 1, 0);
    domain.hi = domain.lo + Vec3(6, 5, 4);
    domain.periodic = c.periodic;
    domain.leesEdwardsOffset = c.leesEdwardsOffset;
    const PeriodicBox box(domain);
    std::vector<Vec3> x(350);
    for (Vec3& p : x)
      p = domain.lo + (domain.hi - domain.lo).cwiseProduct(Vec3(uniform(rng), uniform(rng), uniform(rng)));
    const auto want = allPairsWithin(x, box, c.cutoff);
    const auto got = sorted(findCandidatePairs(x, box, c.cutoff));
    EXPECT_EQ(got, want);
    EXPECT_GT(want.size(), 0u);
  }
}

// The engine puts the image above the box (y + L_y) at x + offset (Simulation::buildGhosts).
TEST(PeriodicBox, LeesEdwardsImageAboveIsShiftedByTheOffset) {
  core::data::Domain domain;
  domain.hi = Vec3(10, 8, 6);
  domain.periodic = {true, true, true};
  domain.leesEdwardsOffset = 3.0;
  const PeriodicBox box(domain);
  const Vec3 top(4.0, 7.8, 1.0), bottom(1.2, 0.1, 1.0);
  const Vec3 imageAbove = bottom + Vec3(3.0, 8.0, 0.0);
  EXPECT_TRUE(box.minimumImage(top - bottom).isApprox(top - imageAbove, 1e-12));
  EXPECT_TRUE(box.minimumImage(bottom - top).isApprox(imageAbove - top, 1e-12));
}

TEST(PeriodicBox, RejectsInconsistentDomains) {
  core::data::Domain flat;
  flat.periodic = {true, false, false};
  EXPECT_THROW(PeriodicBox{flat}, Error);
  core::data::Domain shearedOpen;
  shearedOpen.hi = Vec3(1, 1, 1);
  shearedOpen.periodic = {false, true, true};
  shearedOpen.leesEdwardsOffset = 0.2;
  EXPECT_THROW(PeriodicBox{shearedOpen}, Error);
}

TEST(CandidatePairs, RejectsBadInput) {
  const PeriodicBox open{core::data::Domain{}};
  const std::vector<Vec3> two{Vec3::Zero(), Vec3::UnitX()};
  EXPECT_THROW(findCandidatePairs(two, open, -1.0), Error);
  EXPECT_THROW(findCandidatePairs({Vec3::Zero(), Vec3(std::nan(""), 0, 0)}, open, 1.0), Error);
  EXPECT_TRUE(findCandidatePairs(two, open, 0.5).empty());
  EXPECT_EQ(findCandidatePairs(two, open, 1.0).size(), 1u);
}

}  // namespace
}  // namespace grainbridge::extract::structure
