#pragma once
// `compare_mixture`: a mixture's DEM closures beside the mixture kinetic theories the multi-fluid
// model runs on (issue 60). Gathers extract instances of sheared mixtures (their species' and
// species pairs' closure points, extract/observe/SpeciesClosurePoints) and, at each box's
// state, predicts steady simple shear by each form of closures/MixtureContacts (summed: MFiX's
// SUM_EpsGo; per_phase: the equations as printed) with closures/MixtureSimpleShear. Compared per
// species: the temperature, the partial pressure and its kinetic part, the shear stress, J; per box:
// the temperature ratio of the first two species, the collisional pressure summed over pairs (no
// attribution to species needed) and the dissipation; the temperature ratio also against
// Garzo, Hrenya and Dufty's zeroth order (closures/GhdTemperatureRatio), a theory whose species
// exchange energy in collisions. Writes mixture_comparison.csv, a figure per
// quantity in shear units against the total solid fraction, and findings whose headline says
// which form is closer, where, and by how much.
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class MixtureCompareStage final : public StageType {
 public:
  MixtureCompareStage();
  [[nodiscard]] std::string name() const override { return "compare_mixture"; }
  // 2: the temperature ratio beside Garzo, Hrenya and Dufty's zeroth order
  // 3: rotation_model (the effective restitution of frictional boxes in each phase's dissipation)
  // 4: each species' J (extract 9's species dissipation_rate, the shear work on its partial stress)
  [[nodiscard]] int implVersion() const override { return 4; }
  [[nodiscard]] std::vector<ResultColumn> keyResults() const override { return {{"boxes", "–"}}; }
  [[nodiscard]] std::string summary() const override {
    return "a mixture's DEM closures per species against the summed and per-phase mixture kinetic theories";
  }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] InputMode inputMode() const override { return InputMode::Gather; }
  void checkAgainstUpstream(const nlohmann::json& resolved, const std::string& pointer,
                            const std::vector<UpstreamPlan>& upstream,
                            core::json::Diagnostics& diagnostics) const override;
  void run(StageContext& ctx) const override;

 private:
  params::ParamSchema schema_;
};

}  // namespace grainbridge::workflows::stages
