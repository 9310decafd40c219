#pragma once
// `tfdem`: DEM particles in the averaged gas (engines/tfdem; Section 7.2.3 of the reference). The
// particles are the `dem` stage's (species, contacts, its contact laws and dt), in plane walls on
// every side of the gas's domain; the gas is the `mfm` stage's grid and patches with a fixed step
// fluid_dt of whole DEM steps. A settling phase (settle_duration, the DEM alone, no output) may
// come first; then the run's clock starts. It writes particle frames (their external_force the
// drag alone) and the gas's field frames (gas/), a series at every output interval (pressure drops
// between taps, the particles' mean height, contact and coordination numbers, the multi-contact
// ratio, the gas step's iterations) and a summary of their window means with block-averaging
// errors, and of each tap's dominant frequency (docs/tfdem.md).
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class TfdemStage final : public StageType {
 public:
  TfdemStage();
  [[nodiscard]] std::string name() const override { return "tfdem"; }
  // 5: each gas step closes the gas's continuity with its final fractions (engines/fluid
  //    SimpleStep closeGasContinuity), moving the gas by the size of a continuity residual.
  // 6: the DEM pair loop of dem impl 7 (last bits)
  // 7: the summary records superficial_gas_velocity, which fluidization requires (as mfm 12)
  // 8: block-averaging errors never from a level of fewer than 4 blocks (issue 63)
  // 9: block errors extrapolated to the plateau (issue 63)
  // 10: the DEM pair loop of dem impl 8: frictionless pairs skip the tangential step (last bits;
  //     frictional beds are unchanged to the bit)
  [[nodiscard]] int implVersion() const override { return 10; }
  [[nodiscard]] std::vector<ResultColumn> keyResults() const override {
    return {{"pressure_drop", "Pa"}, {"mean_height", "m"}, {"coordination", "–"}, {"multi_contact_ratio", "–"}};
  }
  [[nodiscard]] std::string summary() const override {
    return "DEM particles coupled to the averaged gas (TF-DEM): particle and gas frames, series";
  }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] InputMode inputMode() const override { return InputMode::None; }
  void checkParams(const nlohmann::json& resolved, const std::string& pointer,
                   core::json::Diagnostics& diagnostics) const override;
  void run(StageContext& ctx) const override;
  // Particle frames over [0, duration] of the run (ids 0..count-1), the summary's pressure drops
  // (the first tap's also as pressure_drop) and mean height, the series' columns.
  [[nodiscard]] std::optional<PlannedOutput> plannedOutput(const nlohmann::json& resolved) const override;

 private:
  params::ParamSchema schema_;
};

}  // namespace grainbridge::workflows::stages
