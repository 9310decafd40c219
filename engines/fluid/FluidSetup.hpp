#pragma once
// The fluid set-up of a continuum engine, declared next to the framework (docs/engine-stages.md,
// section 2): the grid, the boundary patches as the user writes them (a side and a kind by name,
// a jet's ends in metres, inflow speeds and fractions, an outlet's pressure) and the time step's
// limits. Its JSON form uses the keys of the `mfm` stage's params (cells, lengths, boundaries,
// dt, dt_min, dt_max, courant), so a problem found here is reported at the JSON pointer of the
// key the user wrote ("/boundaries/2/to"), and every engine on this framework (mfm, tfdem) checks
// each rule once, here.
#include <array>
#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "core/data/FieldFrame.hpp"
#include "core/engine/SetupProblem.hpp"
#include "engines/fluid/Boundaries.hpp"
#include "engines/fluid/StencilSystem.hpp"
#include "engines/fluid/TimeStepControl.hpp"

namespace grainbridge::fluid {

using core::engine::SetupProblem;

// One boundary patch in the user's terms.
struct PatchSetup {
  std::string side = "y_low";         // x_low, x_high, y_low, y_high, z_low, z_high
  std::string kind = "no_slip_wall";  // no_slip_wall, free_slip_wall, velocity_inlet, pressure_outlet
  // The patch along the side's two tangential axes (x before y before z) [m], on cell faces; both
  // absent: the whole side. A 2D grid ignores the z entry.
  std::optional<std::array<double, 2>> from, to;
  double gasInflow = 0.0;               // gas speed into the domain, normal to the side [m/s]
  std::vector<double> solidsFractions;  // per solids phase entering (outlet: of the backflow); empty: none
  std::vector<double> solidsInflow;     // per solids phase, speed into the domain [m/s]; empty: 0
  // Inlet: per solids phase, the granular temperature the inflow carries [m^2/s^2]; empty: the
  // interior's (zero gradient).
  std::vector<double> solidsTemperature;
  double pressure = 101325.0;  // outlet: the pressure beyond the outlet face [Pa]
};

struct FluidSetup {
  std::array<int, 3> cells{1, 1, 1};   // cells along x, y, z; z = 1: a 2D x-y grid
  Vec3 lengths = Vec3::Ones();         // the domain from the origin [m]; z of a 2D grid: its depth
  std::vector<PatchSetup> boundaries;  // sides no patch covers are no-slip walls
  TimeStepLimits timeStep;             // dt, dt_min, dt_max, courant
  // The key of an engine whose gas step is fixed by construction (tfdem's fluid_dt): the time
  // step's problems are reported there, and the advice is to lower it. Empty: the step is set by
  // dt, dt_min and dt_max and may adapt (mfm).
  std::string fixedStepKey;

  [[nodiscard]] bool twoD() const { return cells[2] == 1; }
  // Cells of lengths / cells from the origin.
  [[nodiscard]] core::data::GridGeometry geometry() const;

  // The most solids a state of these solids fractions (one per phase) may hold: eps_s,max, one
  // value for every composition, or each composition's own (a packing limit by composition).
  using PackedFraction = std::function<double(std::span<const double> solidsFractions)>;

  // Every reason this set-up cannot run `solidsPhases` solids phases packing at most
  // `packedFraction` of an inflow's composition: a grid without cells or extent, the time step's limits, a patch on a
  // side the grid lacks, off its side or off the cell faces, with from without to, with fraction or speed lists of
  // another length than the phases, with more solids than packed, an inlet faster than the Courant limit of a fixed
  // step (dt_min = dt_max), patches that overlap. Empty when it can run.
  [[nodiscard]] std::vector<SetupProblem> problems(std::size_t solidsPhases,
                                                   const PackedFraction& packedFraction) const;
  // The same with one packed fraction for every composition.
  [[nodiscard]] std::vector<SetupProblem> problems(std::size_t solidsPhases, double packedFraction) const {
    return problems(solidsPhases, [packedFraction](std::span<const double>) { return packedFraction; });
  }

  // The patches in the grid's terms: cell ranges and each phase's inflow (the gas first), normal
  // velocities pointing into the domain. Assumes problems() is empty.
  [[nodiscard]] std::vector<BoundaryPatch> patches(std::size_t solidsPhases) const;
};

// How one family of linear systems ("momentum", "pressure", "fraction") is solved, from the keys
// `<family>_solver` (direct | bicgstab | gauss_seidel | petsc), `<family>_solver_tolerance` and
// `<family>_petsc_options`; assumes they were checked against their schema.
[[nodiscard]] LinearSolve linearSolveFromJson(const nlohmann::json& params, const std::string& family);
// What stops a family's solve: petsc in a build without PETSc, or options PETSc refuses (at the
// key `/<family>_solver` or `/<family>_petsc_options`).
[[nodiscard]] std::vector<SetupProblem> linearSolveProblems(const LinearSolve& how, const std::string& family);

// The key a side is written with in a config ("x_low", ..., "z_high"), for a Side.
[[nodiscard]] const char* sideKey(int side);

void to_json(nlohmann::json& j, const PatchSetup& p);
void from_json(const nlohmann::json& j, PatchSetup& p);
void to_json(nlohmann::json& j, const FluidSetup& s);
void from_json(const nlohmann::json& j, FluidSetup& s);

}  // namespace grainbridge::fluid
