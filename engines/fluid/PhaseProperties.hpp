#pragma once
// What a model (engines/mfm's closures, TF-DEM's particle coupling) tells the multiphase solver
// about each phase at the current iterate, cell by cell, and the interphase momentum exchange.
// The stress of phase m is S_m = -P_m I + tau_m with tau_m = 2 mu_m D_m + lambda_m tr(D_m) I
// (Eqs. 3.19-3.20 for the gas, 3.22 and 3.27 for solids): `shearViscosity` and `bulkViscosity`
// are mu_m and lambda_m as they multiply D_m there, so the gas's carry its eps_g (eps_g mu_g,
// Eq. 3.20) and the solids' are the kinetic-theory and plastic viscosities as they stand.
#include <cstddef>
#include <optional>
#include <vector>

#include "engines/fluid/Fields.hpp"

namespace grainbridge::fluid {

struct PhaseProperties {
  explicit PhaseProperties(const StaggeredGrid& grid)
      : density(grid),
        compressibility(grid),
        shearViscosity(grid),
        bulkViscosity(grid),
        solidsPressure(grid),
        plasticPressure(grid),
        solidsPressureSlope(grid),
        wallSlipCoefficient(grid) {}
  CellField density;              // rho_m [kg/m^3]
  CellField compressibility;      // d rho_m / d P_g [s^2/m^2]: M / (R T) for an ideal gas, 0 if incompressible
  CellField shearViscosity;       // mu_m of tau_m [Pa s]
  CellField bulkViscosity;        // lambda_m of tau_m [Pa s]
  CellField solidsPressure;       // P_sm, kinetic plus plastic [Pa]; zero for the gas
  // The plastic part of solidsPressure, eps_sm P* (Eq. 3.26) [Pa]. With several solids phases the
  // momentum equations do not take its own gradient but the phase's volume share of the
  // mixture's, sum_l eps_sl P* (Momentum.hpp).
  CellField plasticPressure;
  CellField solidsPressureSlope;  // dP_sm / d eps_sm [Pa]: what lets the eps_s correction see packing
  // Partial slip at no-slip wall patches (Johnson-Jackson, Eq. 5.8): when set, the phase's
  // tangential velocity at such a wall is not zero but takes the traction -c v_slip, with c
  // the cell's wallSlipCoefficient [kg/(m^2 s)]; Boundaries::apply turns it into the ghost
  // value. Unset (the gas, or solids without it), the patch's own rule holds.
  bool partialSlipWalls = false;
  CellField wallSlipCoefficient;
  // An explicit momentum source on the phase per unit volume [N/m^3], one cell field per axis,
  // averaged to the faces as dragCoefficient is: the particle drag TF-DEM sums per cell and
  // returns to the gas (Eq. 7.32). Empty: none.
  std::vector<CellField> momentumSource;
};

// The solids-solids drag coefficient F_sml (Eq. 3.18) of one pair of solids phases l < m, in
// cells [kg/(m^3 s)]: the momentum exchange -F_sml (v_sl - v_sm) on phase l and its opposite on m.
struct SolidsPairDrag {
  SolidsPairDrag(const StaggeredGrid& grid, std::size_t lPhase, std::size_t mPhase)
      : l(lPhase), m(mPhase), coefficient(grid) {}
  std::size_t l, m;
  CellField coefficient;
};

struct FlowProperties {
  std::vector<PhaseProperties> phases;  // [0] the gas
  // Gas-solids drag coefficient F_gm (Eq. 3.10) per solids phase m = 1..M, in cells [kg/(m^3 s)];
  // dragCoefficient[0] is unused. The solver interpolates it to the faces once, so the gas and
  // the solids momentum equations see the same face value.
  std::vector<CellField> dragCoefficient;
  // Per pair of solids phases the model couples (FlowModel::solidsPairs); empty with one.
  std::vector<SolidsPairDrag> solidsDrag;
  // eps_p of Eq. 3.68 per cell, when the model gives one (FlowModel::packedFractionByCell: a
  // mixture packs by its composition); unset, SimpleSettings::packedFraction holds everywhere.
  std::optional<CellField> packedFraction;
};

}  // namespace grainbridge::fluid
