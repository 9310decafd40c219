#pragma once
// `fluidization`: the pressure-drop curves of bed runs over a range of inflows, read as Fig. 4.5
// is read. Per upstream stage (one per drag-law set, say) it takes each instance's time-averaged
// pressure drop against the superficial gas velocity the instance recorded, finds the plateau
// and the fluidization velocity (engines/mfm/FluidizationCurve), and sets them against what the
// stage recorded the bed to weigh and the drag law's own U_mf: a headline, a table and the figure
// of the curves. It reads the upstream instances' summaries only (DESIGN.md, "Stage contracts"),
// never their params or sweep points, so any engine recording both values (mfm, tfdem) serves.
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class FluidizationStage final : public StageType {
 public:
  FluidizationStage();
  [[nodiscard]] std::string name() const override { return "fluidization"; }
  [[nodiscard]] int implVersion() const override { return 1; }
  [[nodiscard]] std::vector<ResultColumn> keyResults() const override { return {{"curves", "–"}}; }
  [[nodiscard]] std::string summary() const override {
    return "pressure drop against superficial gas velocity of bed runs (mfm, tfdem): plateau against the bed "
           "weight, fluidization against U_mf";
  }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] InputMode inputMode() const override { return InputMode::Gather; }
  // Before any upstream run: every upstream instance will record the summary values `inflow` and
  // `pressure_drop` name.
  void checkAgainstUpstream(const nlohmann::json& resolved, const std::string& pointer,
                            const std::vector<UpstreamPlan>& upstream,
                            core::json::Diagnostics& diagnostics) const override;
  void run(StageContext& ctx) const override;

 private:
  params::ParamSchema schema_;
};

}  // namespace grainbridge::workflows::stages
