// The contacts a multi-pass MST has found by each pass (Figs. 6.14-6.16 take their forces), and
// the frame restricted to them that the force statistics are computed on.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "core/Error.hpp"
#include "extract/statistics/ContactSubset.hpp"
#include "extract/statistics/NormalForces.hpp"
#include "extract/structure/ForceNetworks.hpp"
#include "extract/structure/MstTreeContacts.hpp"
#include "tests/extract/structure/StructureTestFrames.hpp"

namespace grainbridge::extract::structure {
namespace {

using core::data::ParticleFrame;

std::set<std::size_t> repulsiveContacts(const ParticleFrame& f) {
  std::set<std::size_t> out;
  for (std::size_t k = 0; k < f.contacts.size(); ++k) {
    if (f.contacts.forceNormal[k].dot(f.contacts.branch[k]) > 0.0) out.insert(k);
  }
  return out;
}

// A jittered simple-cubic packing, monodisperse with small overlaps like a real one (contact
// lengths 0.87-1, so an elongated edge, >= 1.2 x 0.87, falls behind every unselected contact),
// and no tensile contact (one could split a tree, MultiPassMst.hpp). Pass 1 finds a spanning
// forest of every force network (N_P - 1 contacts per network, the first row of Table 6.2); each
// later pass adds contacts never found before until all are found; no contact is counted twice;
// only repulsive contacts count.
TEST(MstTreeContacts, PassesAddDistinctRepulsiveContactsStartingFromASpanningForest) {
  const ParticleFrame f = testing::latticeFrame(10, 10, 10, true, 1.0, 11);
  MultiPassMstOptions options;
  options.passes = 5;
  const auto mst = runMultiPassMst(f, options);
  const auto networks = analyzeForceNetworks(f);
  const auto repulsive = repulsiveContacts(f);

  const auto first = treeContactsUpToPass(mst, 1);
  EXPECT_EQ(first.size(), networks.particlesInNetworks - networks.networks.size());
  std::vector<std::size_t> previous;
  for (int pass = 1; pass <= options.passes; ++pass) {
    const auto found = treeContactsUpToPass(mst, pass);
    const std::set<std::size_t> distinct(found.begin(), found.end());
    EXPECT_EQ(distinct.size(), found.size()) << "pass " << pass << " counts a contact twice";
    for (const std::size_t k : found) {
      EXPECT_TRUE(repulsive.contains(k)) << "contact " << k << ", pass " << pass;
    }
    ASSERT_GE(found.size(), previous.size());
    EXPECT_TRUE(std::equal(previous.begin(), previous.end(), found.begin())) << "pass " << pass;
    if (pass > 1 && previous.size() < repulsive.size()) {
      EXPECT_GT(found.size(), previous.size()) << "pass " << pass << " found nothing new";
    }
    previous = found;
  }
  // Section 6.3.3: "all the edges have been recovered by a four-pass MST" (but for the large
  // particle's). So here, with coordination 6.
  EXPECT_EQ(treeContactsUpToPass(mst, 4).size(), repulsive.size()) << previous.size() << " of " << repulsive.size();
  EXPECT_THAT([&] { treeContactsUpToPass(mst, 6); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("pass 6 is not in 1..5")));
}

TEST(ContactSubset, KeepsTheListedContactsInOrderAndNothingElseChanges) {
  const ParticleFrame f = testing::randomDenseFrame(200, 0.1, 0.0, 0.0, 3);
  ASSERT_GT(f.contacts.size(), 10u);
  const std::vector<std::size_t> keep = {7, 2, 9};
  const ParticleFrame s = statistics::withContacts(f, keep);
  ASSERT_EQ(s.contacts.size(), 3u);
  EXPECT_NO_THROW(s.validate());
  for (std::size_t e = 0; e < keep.size(); ++e) {
    EXPECT_EQ(s.contacts.i[e], f.contacts.i[keep[e]]);
    EXPECT_EQ(s.contacts.j[e], f.contacts.j[keep[e]]);
    EXPECT_EQ(s.contacts.branch[e], f.contacts.branch[keep[e]]);
    EXPECT_EQ(s.contacts.forceNormal[e], f.contacts.forceNormal[keep[e]]);
    EXPECT_EQ(s.contacts.forceTangentialDissipative[e], f.contacts.forceTangentialDissipative[keep[e]]);
  }
  ParticleFrame same = s;
  same.contacts = f.contacts;
  EXPECT_EQ(same, f);
  EXPECT_THAT([&] { statistics::withContacts(f, std::vector<std::size_t>{f.contacts.size()}); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("beyond the")));
}

}  // namespace
}  // namespace grainbridge::extract::structure
