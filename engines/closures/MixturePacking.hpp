#pragma once
// The packing limit of a mixture of solids phases: the solids fraction at which the cell's
// composition packs, and from it the critical void fraction eps_g* of the plastic regime
// (Eqs. 3.26-3.27) and Eq. 3.68's packed fraction. A mixture of unequal spheres packs denser than
// either kind alone (the small ones fill the large ones' voids), so a cell that demixes near
// packing loses volume to do it.
//
// The reference runs MFiX with two solids phases and gives one eps_g* (0.417, Table 5.2). From
// 2003-08 to 2005-11 every MFiX run with two or more solids phases replaced EP_STAR cell by cell
// by CALC_EP_STAR (calc_p_star.f, calc_mu_s.f of that time), which the reference's runs most
// likely used (issue 55, VALIDATION.md): first Gera's binary formula, from 2005-05 Yu and
// Standish's. Both are here, from the papers:
//
// Yu, A.B. and Standish, N. (1987), Powder Technol. 52:233-241, the linear-mixture packing model
// for n components ordered from coarsest (1) to finest (n), with P_i the packing fraction of
// component i alone and X_j the component's share of the solids volume:
//   P^T  = min_i P_i^T,
//   P_i^T = P_i / (1 - sum_{j != i} (1 - P_i / P_ij) X_j / X_ij),                          (22)
//   P_ij = P_i + P_i (1 - P_i)(1 - 2.35 r_ij + 1.35 r_ij^2)   for r_ij <= 0.741,
//          P_i                                              otherwise,                   (23)
//   X_ij = (1 - r_ij^2) / (2 - P_i)        for j < i (j coarser than i),
//          1 - (1 - r_ij^2) / (2 - P_i)    for j > i,                                      (24)
//   r_ij = d_small / d_large of the pair, <= 1.                                            (25)
// A pair whose diameters differ by less than r = 0.741 adds nothing (P_ij = P_i), so identical
// phases pack as one. (MFiX's function returns the coarsest phase's P when no pair adds anything,
// where the paper gives min_i P_i: they differ only for phases of unequal maximum packing within
// r > 0.741 of each other.)
//
// Fedors, R.F. and Landel, R.F. (1979), Powder Technol. 23:225-231, for a binary mixture of
// coarse (L) and fine (S) spheres, x_L the coarse share of the solids volume, r = d_S / d_L:
//   P = [(P_L - P_S) + (1 - sqrt(r))(1 - P_L) P_S][P_L + (1 - P_L) P_S] x_L / P_L + P_S
//                                        for x_L <= P_L / (P_L + (1 - P_L) P_S),
//   P = (1 - sqrt(r))[P_L + (1 - P_L) P_S](1 - x_L) + P_L      otherwise.
// Gera's CALC_EP_STAR (MFiX 2003) wrote this form with eps_g* held at or above 0.36 (packing at
// most 0.64); `gera` keeps that bound. Gera's code took solids phase 1 as the coarse one whatever
// its diameter; this takes the coarser phase as L, as the paper (and MFiX's later FEDORS_LANDEL)
// does.
//
// With one solids phase every limit is the fixed one, as MFiX called CALC_EP_STAR only with two
// or more; a cell without solids has no composition and takes the coarsest phase's packing alone
// (MFiX's choice below its dilute threshold).
#include <span>
#include <string_view>
#include <vector>

namespace grainbridge::closures {

enum class PackingLimit {
  Fixed,       // "fixed": eps_g* = critical_void_fraction everywhere
  YuStandish,  // "yu_standish": Yu and Standish (1987) from each phase's max_packing
  Gera,        // "gera": Fedors and Landel (1979) as Gera wrote it in MFiX (binary only)
};

[[nodiscard]] std::string_view toString(PackingLimit limit);
// "fixed", "yu_standish" or "gera"; anything else throws grainbridge::Error listing them.
[[nodiscard]] PackingLimit packingLimitFromString(std::string_view name);

// The packing fraction of a mixture by Yu and Standish (Eqs. 22-25 above), phases in any order.
// Throws grainbridge::Error unless the three spans have one entry per phase, every fraction >= 0
// with a positive sum, every diameter > 0 and every packing in (0, 1).
[[nodiscard]] double yuStandishPacking(std::span<const double> solidFractions, std::span<const double> diameters,
                                       std::span<const double> maxPackings);

// The packing fraction of a binary mixture by Fedors and Landel (above), phases in any order,
// without Gera's bound. Throws as yuStandishPacking does, and unless there are exactly two phases.
[[nodiscard]] double fedorsLandelPacking(std::span<const double> solidFractions, std::span<const double> diameters,
                                         std::span<const double> maxPackings);

// Gera's least critical void fraction: packing beyond 0.64 is not taken.
inline constexpr double kGeraLeastVoidFraction = 0.36;

// The critical void fraction of each cell's composition under one limit.
class MixturePacking {
 public:
  // `fixedVoidFraction`: eps_g* of the fixed limit and of one solids phase. `diameters` and
  // `maxPackings` one entry per solids phase (maxPackings unused with Fixed). Throws
  // grainbridge::Error for gera with more than two phases, lists of different lengths, a diameter
  // not positive or a packing outside (0, 1).
  MixturePacking(PackingLimit limit, double fixedVoidFraction, std::vector<double> diameters,
                 std::vector<double> maxPackings);
  [[nodiscard]] PackingLimit limit() const { return limit_; }
  // Whether eps_g* depends on the cell's composition (a limit other than fixed, several phases).
  [[nodiscard]] bool byComposition() const { return limit_ != PackingLimit::Fixed && diameters_.size() > 1; }
  // eps_g* of a cell holding these solids fractions, one per phase.
  [[nodiscard]] double criticalVoidFraction(std::span<const double> solidFractions) const;

 private:
  PackingLimit limit_;
  double fixedVoidFraction_;
  std::vector<double> diameters_, maxPackings_;
  std::vector<std::size_t> order_;  // the phases from coarsest to finest
  double coarsestPacking_ = 0.0;    // the coarsest phase's max packing: an empty cell's
};

}  // namespace grainbridge::closures
