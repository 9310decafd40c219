#pragma once
// Radial distribution function at contact, g0, for one monodisperse solids phase.
//
// The reference names Carnahan & Starling (Section 3.2.3: Lun et al. 1984 took g0 from
// Carnahan and Starling 1969) but prints no formula (VALIDATION.md, multi-fluid engine). MFIX
// uses the same function for a single solids phase: rdf_type CARNAHAN_STARLING in
// model/rdf_mod.f (G_0) and, in mid-2000s MFIX, G_0CS whenever MMAX = 1.
// MFIX's default for several solids phases is Lebowitz (1964), g0 = 1/eps_g + 3 eps/(2 eps_g^2)
// for one phase, which is lower (1.296 against 1.303 at eps = 0.1, 3.33 against 3.70 at
// eps = 0.4); it is not implemented here.
namespace grainbridge::closures {

// Carnahan, N.F. and Starling, K.E. (1969), J. Chem. Phys. 51(2):635-636:
//   g0(eps) = (1 - eps/2) / (1 - eps)^3
//           = 1/(1 - eps) + 3 eps / (2 (1 - eps)^2) + eps^2 / (2 (1 - eps)^3)   (MFIX G_0CS form).
// g0(0) = 1 and g0 grows without bound as eps -> 1; no packing limit is imposed (eps = 0.64
// gives 14.6), so a caller near random close packing must decide what it wants there.
// Throws grainbridge::Error unless 0 <= solidFraction < 1.
[[nodiscard]] double carnahanStarlingG0(double solidFraction);

}  // namespace grainbridge::closures
