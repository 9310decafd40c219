#pragma once
// Verlet list over cell bins with a skin (STYLE.md 12): pairs within a_i + a_j + skin, stored in
// CSR form per owned particle, each pair once. The list is rebuilt
// when some particle has moved more than half the skin. Tangential contact history lives in
// slots parallel to the pairs, so the hot loop reads it with no lookup; at a rebuild it is
// carried over by the pair's global ids, which keeps it across rebuilds and re-sorting.
//
// Inside it, an inner list with a thinner skin holds the pairs the force loop walks: in a dense
// bed with a skin of 0.3 d three in five listed pairs are apart, and each costs the loop a
// distance test and a branch it cannot predict. The inner list is built from this one (no
// binning), in its order, and rebuilt when some particle has moved more than half the inner
// skin; each entry keeps its pair's slot here, where the history stays.
#include <cstdint>
#include <vector>

#include "core/Types.hpp"
#include "engines/dem/Particles.hpp"

namespace grainbridge::dem {

// Tangential history of one pair in contact, keyed by global ids, oriented low id -> high id.
struct PairHistory {
  std::int64_t low;
  std::int64_t high;
  Vec3 ut;
};

class NeighborList {
 public:
  // Bins owned and ghost particles over [lo - cutoff, hi + cutoff] in cells of side >= cutoff
  // (the largest contact distance + skin) and lists every pair closer than its own reach
  // a_i + a_j + skin, once: owned-owned pairs with j > i, owned-ghost pairs only when the owned id
  // is the smaller (the mirrored image pair is listed from the other side). Frozen-frozen pairs
  // are left out. History of pairs still listed is carried over.
  // The per-pair reach matters for size ratios like the Brazil nut's 3.16: with one cutoff set by
  // the largest pair, every small grain would list every grain within 3.5 d0 (about 150) instead
  // of its dozen neighbours, and the force loop would walk them all every step (LAMMPS's
  // `neighbor multi` answers the same problem). The rebuild rule (half-skin displacement) keeps
  // it exact: a pair left out is more than a_i + a_j + skin apart and cannot touch before then.
  // `seed`, when given, replaces the list's own history as the source carried over (restart).
  void build(const Particles& p, const Vec3& lo, const Vec3& hi, double cutoff, double skin,
             const std::vector<PairHistory>* seed = nullptr);
  // The inner list: the listed pairs closer than a_i + a_j + innerSkin, in the list's order. The
  // history of every pair left out is set to zero: such a pair is apart, as the force loop would
  // have found it at this step. Exact until some particle has moved innerSkin / 2 (the same rule
  // as the list's), and so without effect on any result: which pairs it holds only decides
  // which apart pairs the force loop skips.
  void buildInner(const Particles& p, double innerSkin);
  [[nodiscard]] std::size_t innerBegin(std::size_t i) const { return innerOffset_[i]; }
  [[nodiscard]] std::size_t innerEnd(std::size_t i) const { return innerOffset_[i + 1]; }
  [[nodiscard]] std::uint32_t innerPartner(std::size_t k) const { return innerPartner_[k]; }
  [[nodiscard]] std::size_t innerSlot(std::size_t k) const { return innerSlot_[k]; }
  [[nodiscard]] std::size_t innerPairCount() const { return innerPartner_.size(); }
  // The inner list's arrays, for the force loop to hold in registers: through the member
  // functions above GCC reloads each array's address after every store of a force (it cannot
  // prove that a store of a double or a count leaves a std::vector's pointers alone).
  struct InnerView {
    const std::size_t* offset;
    const std::uint32_t* partner;
    const std::size_t* slot;
    Vec3* history;
  };
  [[nodiscard]] InnerView innerView() {
    return {innerOffset_.data(), innerPartner_.data(), innerSlot_.data(), history_.data()};
  }
  // Positions of owned particles at the last inner build, for its rebuild criterion.
  [[nodiscard]] const std::vector<Vec3>& innerReferencePositions() const { return x1_; }

  // The history of every pair currently in contact (for checkpoints).
  [[nodiscard]] std::vector<PairHistory> exportHistory() const;

  // Cells of the grid build() bins into over [lo - cutoff, hi + cutoff]: floor(extent / cutoff)
  // per axis, at least 1, as a double so that an absurd request is a number, not an overflow.
  [[nodiscard]] static double gridCells(const Vec3& lo, const Vec3& hi, double cutoff);
  // The most cells one list may take: 2^28, 1 GiB of 4-byte cell starts. A box of 10^4 grain
  // diameters per side would need about 5e11: that is a mistaken unit or box, refused at set-up
  // (SimulationSetup::problems) with the parameter named, not a length_error mid-run.
  static constexpr double kMaxGridCells = 268435456.0;

  [[nodiscard]] std::size_t pairCount() const { return partner_.size(); }
  [[nodiscard]] std::size_t begin(std::size_t i) const { return offset_[i]; }
  [[nodiscard]] std::size_t end(std::size_t i) const { return offset_[i + 1]; }
  [[nodiscard]] std::uint32_t partner(std::size_t slot) const { return partner_[slot]; }
  Vec3& history(std::size_t slot) { return history_[slot]; }
  [[nodiscard]] const Vec3& history(std::size_t slot) const { return history_[slot]; }

  // Positions of owned particles at the last build, for the half-skin rebuild criterion.
  [[nodiscard]] const std::vector<Vec3>& referencePositions() const { return x0_; }
  [[nodiscard]] std::int64_t builds() const { return builds_; }
  [[nodiscard]] std::int64_t innerBuilds() const { return innerBuilds_; }

 private:
  std::vector<std::size_t> offset_;
  std::vector<std::uint32_t> partner_;
  std::vector<Vec3> history_;  // u_t of Eq. 6.4 in the orientation (owner i, partner j); 0 = no contact
  std::vector<Vec3> x0_;
  std::vector<std::int64_t> idsAtBuild_;  // global ids by index at the last build, to key history
  std::int64_t builds_ = 0;
  std::int64_t innerBuilds_ = 0;
  std::vector<std::size_t> innerOffset_;
  std::vector<std::uint32_t> innerPartner_;
  std::vector<std::size_t> innerSlot_;
  std::vector<Vec3> x1_;
  // Scratch kept between builds to avoid reallocating.
  std::vector<std::uint32_t> cellStart_;
  std::vector<std::uint32_t> cellItems_;
  std::vector<std::uint32_t> cellOf_;
  std::vector<std::uint32_t> candidates_;  // one particle's candidates, in cell order
};

}  // namespace grainbridge::dem
