#pragma once
// What a fluidization curve is read against (Fig. 4.5), from the set-up alone: the initial bed's
// solids volume per phase and its buoyant weight per unit area of the bottom,
//   W = sum_m V_m (rho_m - rho_g) |g| / A = (1 - eps_g) (rho_s - rho_g) g H for one uniform phase,
// the plateau a fluidized bed's pressure drop reaches; and the minimum fluidization velocity the
// drag law implies at the first region holding solids (engines/closures/MinimumFluidization),
// with which a curve's own U_mf (FluidizationCurve.hpp) is compared. The gas density is taken at
// the reference pressure. Both are the same whether a run starts fresh or resumes.
#include <optional>
#include <vector>

#include "engines/mfm/InitialRegions.hpp"
#include "engines/mfm/MfmEngine.hpp"

namespace grainbridge::mfm {

struct InitialInventory {
  std::vector<double> solidsVolume;  // V_m per solids phase [m^3] (per unit depth in 2D)
  double buoyantWeight = 0.0;        // W [Pa]
};

// Fills the regions into a flow state of the set-up's grid (applyRegions: the same fractions,
// perturbation included, as a fresh engine's) and measures them; builds no engine.
[[nodiscard]] InitialInventory initialInventory(const MultiFluidSetup& setup, const InitialState& initial);

// U_mf [m/s] of phase 1's particles at the void fraction of the first region whose solids
// fractions sum above zero; std::nullopt without solids phases or such a region. Throws
// grainbridge::Error when the drag law does not carry the bed.
[[nodiscard]] std::optional<double> dragMinimumFluidizationVelocity(const MultiFluidSetup& setup,
                                                                    const InitialState& initial);

}  // namespace grainbridge::mfm
