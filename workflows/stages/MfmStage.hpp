#pragma once
// `mfm`: a multi-fluid (two-fluid) run of gas and M solids continua (engines/mfm; Chapters 3-4
// of the reference) on a staggered grid, with boundary patches (walls, inlets and jets, pressure
// outlets) and initial regions. It writes field frames (HDF5 + XDMF), a series at every output
// interval (pressure drops between taps, Eq. 5.22 mean particle heights, solids volumes, the
// solver's step), time-averaged fields with block-averaging errors over the averaging window,
// and a summary of the time-averaged pressure drops and heights with their errors. The solids
// closures are kinetic theory (`ktgf`) or DEM closure tables (`table`) the executor loads from
// the workflow database (docs/multi-fluid.md).
#include "workflows/stages/ClosureSamples.hpp"
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class MfmStage final : public StageType {
 public:
  MfmStage();
  [[nodiscard]] std::string name() const override { return "mfm"; }
  // 2: the summary gains bed_weight and drag_umf, series.csv the solver's step and iteration
  //    counts and last residual
  // 3: the granular-energy equation with lun1984 the default, Johnson-Jackson walls, rotation.
  // 4: products for downstream stages instead of params: field frames carry their materials
  //    (gravity, each phase's name, diameter, density); the summary gains closure,
  //    pressure_drop_tap and solids_volume_change_<phase>, mean_height is Eq. 5.22 over all
  //    solids (a mono bed's is its phase's, as before); the mean fields are mean_field_frame.
  // 5: positivity-preserving solids faces (engines/fluid MassFlux).
  // 6: each converged step closes every solids phase's continuity implicitly (no undershoot).
  // 7: with several solids phases each feels its volume share of the mixture's plastic pressure
  //    gradient (engines/fluid Momentum); one solids phase unchanged bit for bit.
  // 8: with several solids phases a cell without solids has no kinetic viscosity or conductivity
  //    (was the pure granular gas's); one solids phase unchanged bit for bit.
  // 9: series and summary carry each phase's boundary mass account (mass_<phase>, mass_in_,
  //    mass_out_ and per outlet, mass_balance_).
  // 10: at a pressure outlet a solids phase's ghost repeats the interior whichever way the phase
  //     moves (what it brings back in is still the backflow state's, engines/fluid MassFlux).
  // 11: each transient step closes the gas's continuity with its final fractions (engines/fluid
  //     SimpleStep closeGasContinuity): an incompressible gas's balance exact, every field moved
  //     by the size of a continuity residual.
  // 12: the summary records superficial_gas_velocity, which fluidization requires (a run cached
  //     without it could not feed one).
  // 13: series.csv carries plastic_solids_share and each phase's theta_<phase>; the packing
  //     limit by composition and the per-phase mixture kinetic theory (defaults unchanged).
  // 14: segregation_percentage in percent (Eq. 5.23 times 100), as its name says (issue 62).
  // 15: retried_iterations (detect_stall); 16: the point-coupled faces' closed-form inverses
  // 17: block-averaging errors never from a level of fewer than 4 blocks (issue 63)
  // 18: block errors extrapolated to the plateau; joint closure samples correlated (issue 63)
  // 19: a pressure outlet with a solids backflow lets it in where the interior holds none (issue 56)
  // 20: the algebraic theta is zero where eps_s <= 1e-15, as MFiX's (it overflowed in round-off
  //     solids and failed the fraction correction; issue 56)
  // 21: an empty or round-off negative ghost brings no solids into the closing continuity solve
  //     (a negative one fed back on itself at outlets; issue 56)
  [[nodiscard]] int implVersion() const override { return 21; }
  [[nodiscard]] std::vector<ResultColumn> keyResults() const override {
    return {{"pressure_drop", "Pa"}, {"mean_height", "m"}, {"solver_steps", "–"}, {"retries", "–"}};
  }
  [[nodiscard]] std::string summary() const override {
    return "multi-fluid gas-solids flow (two-fluid model): staggered grid, modified SIMPLE, frames and series";
  }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  // `from` only names the tabulate stages whose tables a `table` closure reads.
  [[nodiscard]] InputMode inputMode() const override { return InputMode::PerInstance; }
  void checkParams(const nlohmann::json& resolved, const std::string& pointer,
                   core::json::Diagnostics& diagnostics) const override;
  void checkAgainstUpstream(const nlohmann::json& resolved, const std::string& pointer,
                            const std::vector<UpstreamPlan>& upstream,
                            core::json::Diagnostics& diagnostics) const override;
  // closure "table": closure_table's p_theta, eta_theta and j_theta, as table_quantities names.
  [[nodiscard]] std::vector<ClosureTableRef> closureTables(const nlohmann::json& resolved) const override;
  // closure "table" with closure_samples or closure_samples_per_quantity: the nominal run and its
  // closure samples (workflows/stages/ClosureSamples.hpp).
  [[nodiscard]] std::vector<Replica> replicas(const nlohmann::json& resolved) const override;
  [[nodiscard]] std::vector<std::string> replicaSummaryKeys() const override {
    return {kClosureSampleKey, kClosurePerturbedKey};
  }
  [[nodiscard]] std::string tableErrorsNeededBy(const nlohmann::json& resolved) const override;
  // plastic mu_i: a rheology of other grains than the solids phase's is refused at /rheology.
  void checkTableGrains(const nlohmann::json& resolved, const std::string& pointer, const ClosureTableRef& ref,
                        const Grains& grains, core::json::Diagnostics& diagnostics) const override;
  void run(StageContext& ctx) const override;
  // Field frames with their materials, the mean fields (with an averaging window), and the
  // summary's pressure drops (one per tap, the first also as pressure_drop), heights and solids
  // inventory changes per phase, and a closure sample's closure_sample and closure_perturbed, for
  // the checks of the stages that read them (fluidization, bed_compare).
  [[nodiscard]] std::optional<PlannedOutput> plannedOutput(const nlohmann::json& resolved) const override;

 private:
  params::ParamSchema schema_;
};

}  // namespace grainbridge::workflows::stages
