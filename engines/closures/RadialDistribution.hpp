#pragma once
// Radial distribution function at contact, g0, for one monodisperse solids phase.
//
// The reference names Carnahan & Starling (Section 3.2.3: Lun et al. 1984 took g0 from
// Carnahan and Starling 1969) but prints no formula (VALIDATION.md, multi-fluid engine). MFIX
// uses the same function for a single solids phase: rdf_type CARNAHAN_STARLING in
// model/rdf_mod.f (G_0) and, in mid-2000s MFIX, G_0CS whenever MMAX = 1.
// For several solids phases MFIX of the reference's time switched to Lebowitz (1964)
// automatically (VALIDATION.md): lebowitzG0 below, the mixture default. Ma and Ahmadi's g0 is a
// named variant with a packing limit.
#include <span>
#include <vector>

namespace grainbridge::closures {

// Carnahan, N.F. and Starling, K.E. (1969), J. Chem. Phys. 51(2):635-636:
//   g0(eps) = (1 - eps/2) / (1 - eps)^3
//           = 1/(1 - eps) + 3 eps / (2 (1 - eps)^2) + eps^2 / (2 (1 - eps)^3)   (MFIX G_0CS form).
// g0(0) = 1 and g0 grows without bound as eps -> 1; no packing limit is imposed (eps = 0.64
// gives 14.6), so a caller near random close packing must decide what it wants there.
// Throws grainbridge::Error unless 0 <= solidFraction < 1.
[[nodiscard]] double carnahanStarlingG0(double solidFraction);

// Lebowitz, J.L. (1964), Phys. Rev. 133(4A):A895-A899, for hard-sphere mixtures, as MFIX writes
// it (model/rdf_mod.f, G_0 with rdf LEBOWITZ):
//   g0_lm = 1/eps_g + 3 d_l d_m / (eps_g^2 (d_l + d_m)) sum_k eps_k / d_k
// For one phase: 1/eps_g + 3 eps/(2 eps_g^2), below Carnahan-Starling (1.296 against 1.303 at
// eps = 0.1, 3.33 against 3.70 at 0.4). It has no packing limit below eps_g = 0: it stays finite
// up to close packing (10.19 at one phase's eps 0.64). Throws grainbridge::Error unless
// sum eps_k < 1 (eps_g > 0), every eps_k >= 0, every d_k > 0, and l, m index the phases.
[[nodiscard]] double lebowitzG0(const std::vector<double>& solidFractions, const std::vector<double>& diameters,
                                std::size_t l, std::size_t m);

// The same for every pair of one mixture state: the sums over the phases taken once (a mixture's
// kinetic theory asks for M^2 pairs per cell), each g0_lm then as lebowitzG0 gives it, bit for bit.
// Throws as lebowitzG0 does; `diameters` must outlive it (the fractions are read once here).
class LebowitzMixture {
 public:
  LebowitzMixture(std::span<const double> solidFractions, const std::vector<double>& diameters);
  // Inline, with its error out of line: a binary bed asks for about 30 pairs per cell and
  // iteration, and the error path's stack frame made each call cost as much as its arithmetic.
  [[nodiscard]] double g0(std::size_t l, std::size_t m) const {
    const std::vector<double>& d = *diameters_;
    if (l >= d.size() || m >= d.size()) throwPhaseOutOfRange(l, m);
    return 1.0 / voidFraction_ + 3.0 * d[l] * d[m] / (voidFraction_ * voidFraction_ * (d[l] + d[m])) * sumOverDiameter_;
  }

 private:
  [[noreturn]] void throwPhaseOutOfRange(std::size_t l, std::size_t m) const;
  const std::vector<double>* diameters_;
  double voidFraction_ = 1.0, sumOverDiameter_ = 0.0;
};

// Ma, D. and Ahmadi, G. (1986), J. Chem. Phys. 84(6):3449-3450, `ma_ahmadi_g0` (not lun1984's
// Ma-Ahmadi gas modification of the viscosity):
//   g0 = (1 + 2.5 eps + 4.5904 eps^2 + 4.515439 eps^3) / (1 - (eps / eps_max)^3)^0.67802,
//   eps_max = 0.64356 (random close packing).
// It diverges at eps_max and is undefined beyond; at or above it this throws grainbridge::Error
// naming the value and the limit (a solver keeps eps_s below it with the plastic regime,
// Eqs. 3.26-3.27, switched at eps_s* = 1 - eps_g* < eps_max). Throws for eps < 0 too.
inline constexpr double kMaAhmadiPackingLimit = 0.64356;

// The default g0 of a multi-fluid run, as MFIX of the reference's time chose it: Carnahan-
// Starling for one solids phase, Lebowitz as soon as there are several (VALIDATION.md).
[[nodiscard]] double defaultG0(const std::vector<double>& solidFractions, const std::vector<double>& diameters,
                               std::size_t l, std::size_t m);
[[nodiscard]] double maAhmadiG0(double solidFraction);

}  // namespace grainbridge::closures
