#pragma once
// The multi-fluid engine's set-up (docs/engine-stages.md, section 2): the grid and its patches,
// the phases and their closures, the SIMPLE solver's settings and the time step. Its JSON form
// uses the `mfm` stage's keys (from_json), and problems() lists every reason it cannot start at
// the pointer of the key at fault, so the stage's config check and its run see one list and each
// physics rule is written once, here: g0 against the number of phases, the algebraic granular
// energy's limits, a closure table's and a mu(I) rheology's conditions, the fluid set-up's own.
//
// What the engine runs on is resolved (geometry, patches, model, settings); what the user chose
// is kept beside it as written (the fluid set-up, the solids pairs, the table and rheology
// choices), for problems() and for the DEM data a run reads before it starts (useClosureTables,
// useRheology). A set-up built in code (tests) may leave the choices at their defaults.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/LoadedClosureTable.hpp"
#include "core/LoadedRheology.hpp"
#include "core/data/FieldFrame.hpp"
#include "core/engine/SetupProblem.hpp"
#include "engines/closures/TabulatedClosure.hpp"
#include "engines/fluid/FluidSetup.hpp"
#include "engines/mfm/MultiFluidEngine.hpp"
#include "engines/mfm/SolidsPairs.hpp"

namespace grainbridge::mfm {

using core::engine::SetupProblem;

// closure "table": the DEM closure tables the granular-energy form reads, as written.
struct TableClosureChoice {
  std::string tables;                                    // closure_table; empty when not given
  std::optional<closures::OutOfRangePolicy> outOfRange;  // out_of_range; none when not given
  std::vector<std::string> quantities;                   // table_quantities: pressure, shear_viscosity, dissipation
};

// The plastic viscosity: Schaeffer's, or mu(I) from a DEM rheology (PlasticRegime.hpp).
struct PlasticViscosityChoice {
  bool inertial = false;  // plastic "mu_i"
  std::string rheology;   // the rheology's name (a tabulate stage's table); empty when not given
  bool fitted = true;     // rheology_form "fit"; false: "table", its measured points
};

// Everything that builds a MultiFluidEngine, so a restore rebuilds the same one.
struct MultiFluidSetup {
  core::data::GridGeometry geometry;
  std::vector<fluid::BoundaryPatch> patches;
  MultiFluidParams model;
  fluid::SimpleSettings settings;
  fluid::TimeStepLimits limits;
  double interval = 0.01;  // the driver's step [s]

  // As written (from_json); problems() checks them.
  fluid::FluidSetup fluid;
  std::vector<SolidsPairRequest> pairRequests;
  std::optional<TableClosureChoice> table;
  PlasticViscosityChoice plasticViscosity;
  bool packedFractionGiven = false;  // packed_solids_fraction written (not 1 - critical_void_fraction)

  // Every reason the engine cannot start, at the pointer of the `mfm` key at fault; empty when it
  // can. The closure tables and the rheology are checked when they are read (below).
  [[nodiscard]] std::vector<SetupProblem> problems() const;
  // eps_s,max of a state of these solids fractions: 1 - eps_g* of its composition under a packing
  // limit by composition (MixturePacking), else the one packed fraction (Eq. 3.68's eps_p).
  // What a feed or an initial region may hold; the one packed fraction where the packing's keys are
  // at fault (problems() names them).
  [[nodiscard]] fluid::FluidSetup::PackedFraction packedFraction() const;
};

// The set-up from the `mfm` stage's resolved params (SI); assumes each key passed its schema.
void from_json(const nlohmann::json& j, MultiFluidSetup& s);

// closure "table": the closure model on `tables` (those of the run's closure_table), the kinetic
// theory for what they lack. Problems: a table of frictional grains with the rotation model, which
// would count their friction twice.
[[nodiscard]] std::vector<SetupProblem> useClosureTables(MultiFluidSetup& s,
                                                         const std::vector<core::LoadedClosureTable>& tables);

// plastic "mu_i": the plastic viscosity from the rheology the set-up names among `rheologies`, at
// the solids phase's restitution, as its fit or its points. Problems: the rheology not loaded, of
// other grains, without a row at that restitution or without a fit.
[[nodiscard]] std::vector<SetupProblem> useRheology(MultiFluidSetup& s,
                                                    const std::vector<core::LoadedRheology>& rheologies);

// Why `solids` cannot take the mu(I) rheology `name` measured on grains of `diameter` and
// `density` (another grain: I would be formed with the wrong grains), or "" when it can.
[[nodiscard]] std::string rheologyGrainsProblem(const SolidsPhase& solids, const std::string& name, double diameter,
                                                double density);

}  // namespace grainbridge::mfm
