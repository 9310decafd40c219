#pragma once
// What a researcher reads off a fluidized bed while it runs (the series of an mfm stage; from the
// grid and the FlowState only, so any engine with a gas phase, TF-DEM too, reads the same):
//   the gas pressure drop between two heights along gravity, interpolated linearly between cell
//   centres and averaged across the bed (Fig. 4.5's Delta P, with the heights the experiment's
//   taps had);
//   the mean particle height of Eq. 5.22, sum eps_s h / sum eps_s, weighted by cell volume too
//   (VALIDATION.md: on a non-uniform grid), measured from the domain's low side along gravity;
//   the solids volume of each phase (mass divided by its density), which a walled bed keeps.
#include <vector>

#include "engines/fluid/FlowState.hpp"

namespace grainbridge::fluid {

// The axis gravity points along (the largest |g| component) and its sign: heights grow
// against gravity.
struct VerticalAxis {
  int axis = 1;
  double up = 1.0;  // +1: height grows with the axis coordinate
};
[[nodiscard]] VerticalAxis verticalAxis(const Vec3& gravity);

// The area of the domain's bottom [m^2]: the product of its horizontal extents (what a bed's weight
// per unit area divides by).
[[nodiscard]] double bottomArea(const core::data::GridGeometry& geometry, VerticalAxis vertical);

// P_g at height h [m] above the domain's bottom, averaged over the cells of that height; between
// cell centres linearly, below the first centre extrapolated from the first two (the inlet face).
[[nodiscard]] double pressureAtHeight(const FlowState& state, VerticalAxis vertical, double height);

// Eq. 5.22 for solids phase m [m]; 0 when the phase holds no solids.
[[nodiscard]] double meanParticleHeight(const FlowState& state, VerticalAxis vertical, std::size_t m);

// Eq. 5.22 over all solids from each phase's mean height and solids volume (the two above, one
// entry per phase): sum_m h_m V_m / sum_m V_m, since each h_m is its phase's volume-weighted
// mean; 0 when the bed holds no solids.
[[nodiscard]] double mixtureMeanHeight(const std::vector<double>& heights, const std::vector<double>& volumes);

// The segregation percentage of a binary bed, Eqs. 5.23-5.25, in percent: s_p = 100 (S_p - 1) /
// (S_p,max - 1) with S_p = <h_small> / <h_large> (Eq. 5.22 of each phase) and S_p,max = (2 - x) /
// (1 - x), the S_p of a fully separated bed with the small particles on top, x the small
// particles' share of the solids volume. 0 for a perfectly mixed bed, 100 for a fully separated
// one. Eq. 5.23 writes the fraction; its name (Goldschmidt et al. 2003) says percent, and every
// output, table and figure gives it so (issue 62). Throws grainbridge::Error for x outside (0, 1)
// or heights that are not positive.
[[nodiscard]] double segregationPercentage(double smallHeight, double largeHeight, double smallShare);

// The volume of solids phase m in the domain [m^3] (per unit depth in 2D: the cell volume uses
// the z spacing, which a 2D grid sets to its depth).
[[nodiscard]] double solidsVolume(const FlowState& state, std::size_t m);

// The granular temperature of solids phase m weighted by its solids volume over the domain,
// sum eps_m theta_m / sum eps_m [m^2/s^2]; 0 when the phase holds no solids.
[[nodiscard]] double meanGranularTemperature(const FlowState& state, std::size_t m);

}  // namespace grainbridge::fluid
