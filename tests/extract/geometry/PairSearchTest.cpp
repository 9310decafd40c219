// The cell-list pair search finds exactly the pairs an all-pairs loop finds, each once and with
// the same minimum-image length (bitwise for Lengths::Exact, to round-off for RoundOff), in open,
// periodic, mixed and Lees-Edwards boxes (offset beyond the box included), for points stored
// outside the box, for sparse sets on coarsened cells and for cutoffs past half the box or many
// boxes long; with exact lengths also pairs at exactly the cutoff.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "core/Error.hpp"
#include "extract/geometry/PairSearch.hpp"
#include "extract/geometry/PeriodicBox.hpp"

namespace grainbridge::extract::geometry {
namespace {

using core::data::Domain;
// (i, j, length) in index order.
using PairLengths = std::vector<std::tuple<std::size_t, std::size_t, double>>;

PairLengths allPairsWithin(const std::vector<Vec3>& p, const PeriodicBox& box, double cutoff) {
  PairLengths out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double r = box.minimumImage(p[i] - p[j]).norm();
      if (r <= cutoff) out.emplace_back(i, j, r);
    }
  }
  return out;
}

// The search's pairs in index order; counts pairs out of order or found twice.
PairLengths searched(const std::vector<Vec3>& p, const PeriodicBox& box, double cutoff, int& bad,
                     PairSearch::Lengths lengths = PairSearch::Lengths::Exact) {
  PairLengths out;
  PairSearch(box, p, cutoff, lengths).forEachPair([&](std::size_t i, std::size_t j, double r) {
    bad += i < j ? 0 : 1;
    out.emplace_back(i, j, r);
  });
  std::sort(out.begin(), out.end());
  for (std::size_t k = 1; k < out.size(); ++k) {
    bad += std::get<0>(out[k - 1]) == std::get<0>(out[k]) && std::get<1>(out[k - 1]) == std::get<1>(out[k]) ? 1 : 0;
  }
  return out;
}

struct Case {
  std::string name;
  Domain domain;
  double cutoff;
};

std::vector<Case> cases() {
  Domain full;
  full.lo = Vec3(-1, 0, 2);
  full.hi = Vec3(9, 8, 10);
  full.periodic = {true, true, true};
  Domain sheared = full;
  sheared.leesEdwardsOffset = 3.7;
  sheared.leesEdwardsShearRate = 0.1;
  Domain longSheared = sheared;  // many cells along x: the shifted x range of the fixed-image path
  longSheared.hi = Vec3(29, 8, 10);
  Domain open = full;
  open.periodic = {false, false, false};
  Domain mixed = full;
  mixed.periodic = {true, false, true};
  Domain xOnly = full;
  xOnly.periodic = {true, false, false};
  Domain small;  // 6 x 5 x 4
  small.lo = Vec3(-2, 1, 0);
  small.hi = small.lo + Vec3(6, 5, 4);
  small.periodic = {true, true, true};
  Domain smallSheared = small;
  smallSheared.leesEdwardsOffset = 2.35;
  Domain offsetBeyondTheBox = small;
  offsetBeyondTheBox.leesEdwardsOffset = 7.9;
  return {
      {"periodic", full, 1.3},
      {"periodic, wide cutoff", full, 2.9},
      {"Lees-Edwards", sheared, 1.7},
      // Four cells along y for a reach of two: cells reachable through two images.
      {"Lees-Edwards, cells reached through two images", sheared, 3.9},
      {"Lees-Edwards, long in x", longSheared, 1.7},
      {"open", open, 1.5},
      {"periodic x and z", mixed, 2.2},
      {"periodic x only", xOnly, 2.1},
      {"Lees-Edwards, offset beyond the box", offsetBeyondTheBox, 1.1},
      {"periodic, cutoff past half the box", small, 3.5},
      {"Lees-Edwards, cutoff past half the box", smallSheared, 3.5},
      {"Lees-Edwards, cutoff many boxes long", smallSheared, 1e3},
  };
}

// n points in the box of d and up to half a unit outside it.
std::vector<Vec3> pointsAround(const Domain& d, int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> ux(d.lo[0] - 0.5, d.hi[0] + 0.5), uy(d.lo[1] - 0.5, d.hi[1] + 0.5),
      uz(d.lo[2] - 0.5, d.hi[2] + 0.5);
  std::vector<Vec3> p;
  for (int k = 0; k < n; ++k) p.emplace_back(ux(rng), uy(rng), uz(rng));
  return p;
}

TEST(PairSearch, ExactLengthsEqualAllPairsInEveryKindOfBox) {
  std::mt19937_64 rng(42);
  for (const Case& c : cases()) {
    // 700 points: cells of about cutoff / 2; 20 points: cells coarsened to at most 64.
    for (const int count : {700, 20}) {
      SCOPED_TRACE(c.name + ", " + std::to_string(count) + " points");
      const std::vector<Vec3> p = pointsAround(c.domain, count, rng);
      const PeriodicBox box(c.domain);
      const PairLengths want = allPairsWithin(p, box, c.cutoff);
      int bad = 0;
      const PairLengths got = searched(p, box, c.cutoff, bad);
      EXPECT_EQ(bad, 0);
      EXPECT_EQ(got, want);  // the same pairs with bitwise the same lengths
      EXPECT_GT(want.size(), 0u);
    }
  }
}

TEST(PairSearch, RoundOffLengthsEqualAllPairsToRoundOff) {
  std::mt19937_64 rng(43);
  for (const Case& c : cases()) {
    for (const int count : {700, 20}) {
      SCOPED_TRACE(c.name + ", " + std::to_string(count) + " points");
      const std::vector<Vec3> p = pointsAround(c.domain, count, rng);
      const PeriodicBox box(c.domain);
      const PairLengths want = allPairsWithin(p, box, c.cutoff);
      int bad = 0;
      const PairLengths got = searched(p, box, c.cutoff, bad, PairSearch::Lengths::RoundOff);
      EXPECT_EQ(bad, 0);
      ASSERT_EQ(got.size(), want.size());
      for (std::size_t k = 0; k < want.size(); ++k) {
        ASSERT_EQ(std::get<0>(got[k]), std::get<0>(want[k]));
        ASSERT_EQ(std::get<1>(got[k]), std::get<1>(want[k]));
        EXPECT_NEAR(std::get<2>(got[k]), std::get<2>(want[k]), 1e-12);
      }
    }
  }
}

TEST(PairSearch, ExactLengthsKeepPairsAtExactlyTheCutoff) {
  // The cutoff is the length of one of the pairs (the MST's cutoff is a contact length times
  // the elongation factor, which may be 1), so the cells and the cheap test need their
  // round-off margin for it to be found.
  std::mt19937_64 rng(44);
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::vector<Vec3> p = pointsAround(c.domain, 300, rng);
    const PeriodicBox box(c.domain);
    PairLengths all = allPairsWithin(p, box, c.cutoff);
    ASSERT_GT(all.size(), 10u);
    std::sort(all.begin(), all.end(), [](const auto& x, const auto& y) { return std::get<2>(x) < std::get<2>(y); });
    for (const std::size_t rank : {std::size_t{0}, all.size() / 2, all.size() - 1}) {
      const double cutoff = std::get<2>(all[rank]);
      int bad = 0;
      EXPECT_EQ(searched(p, box, cutoff, bad), allPairsWithin(p, box, cutoff));
      EXPECT_EQ(bad, 0);
    }
  }
}

TEST(PairSearch, CutoffIsInclusiveAndMayBeZero) {
  const PeriodicBox open{Domain{}};
  const std::vector<Vec3> two{Vec3::Zero(), Vec3::UnitX()};
  int bad = 0;
  EXPECT_TRUE(searched(two, open, 0.5, bad).empty());
  EXPECT_EQ(searched(two, open, 1.0, bad).size(), 1u);
  const std::vector<Vec3> coincident{Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 4)};
  EXPECT_EQ(searched(coincident, open, 0.0, bad).size(), 1u);
  EXPECT_EQ(searched(coincident, open, 0.0, bad, PairSearch::Lengths::RoundOff).size(), 1u);
  EXPECT_EQ(searched(two, open, 1.0, bad, PairSearch::Lengths::RoundOff).size(), 1u);
  EXPECT_EQ(bad, 0);
  EXPECT_TRUE(searched({}, open, 1.0, bad).empty());
}

TEST(PairSearch, RejectsBadInput) {
  const PeriodicBox open{Domain{}};
  const std::vector<Vec3> two{Vec3::Zero(), Vec3::UnitX()};
  EXPECT_THROW(PairSearch(open, two, -1.0), Error);
  EXPECT_THROW(PairSearch(open, two, std::nan("")), Error);
  EXPECT_THROW(PairSearch(open, std::vector<Vec3>{Vec3::Zero(), Vec3(std::nan(""), 0, 0)}, 1.0), Error);
}

}  // namespace
}  // namespace grainbridge::extract::geometry
