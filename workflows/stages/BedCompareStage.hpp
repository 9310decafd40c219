#pragma once
// `bed_compare`: fluidized-bed runs of the multi-fluid model side by side, with the numbers they
// are judged by. Gathers mfm instances (a sweep, or one bed under `ktgf` and one under `table`)
// and, per run: the time-averaged Eq. 5.22 mean particle height and pressure drop with their
// block-averaging errors, each against the reference values the config names for it (the
// reference's Table 5.3, an experiment), the pressure fluctuation's dominant frequency, and the
// share of the bed a closure table covered (by cell-steps and by solids volume). Figures: the
// time-averaged solid-fraction maps side by side on one colour scale, the time-averaged heights
// beside the reference values, and the mean particle height and the pressure drop against
// time. Runs that differ only in a seed (`realisations`) form an arm: its mean, standard deviation
// and standard error over them, and the difference between two arms in standard errors (arms.csv).
// Findings lead the report; beds.csv has every number.
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class BedCompareStage final : public StageType {
 public:
  BedCompareStage();
  [[nodiscard]] std::string name() const override { return "bed_compare"; }
  // 2: beds.csv and the table gain the segregation percentage of binary beds.
  // 3: figures as wide as their title and legend need (report/Plot): a sweep's long run labels
  //    ran off the right edge.
  // 5: closure samples (issue 31) join their nominal run: beds.csv gains closure_samples and each
  //    output's spread from the DEM closures with each table quantity's share; the findings lead
  //    with it and the heights figure draws it beside the block-averaging error.
  // 7: statistics over realisations (issue 55): arms.csv, the arms' means and standard errors
  //    and their differences in the findings, the figure segregation_realisations; summary arms.
  // 8: a colour per run, runs by name along x, s_p in percent, figures against time at a page's
  //    full width, the reference series and statements beside the runs (issue 62).
  // 9: the findings table names a run as the legends do (what differs between the runs).
  [[nodiscard]] int implVersion() const override { return 9; }
  [[nodiscard]] std::vector<ResultColumn> keyResults() const override { return {{"beds", "–"}, {"arms", "–"}}; }
  [[nodiscard]] std::string summary() const override {
    return "bed runs (mfm, tfdem) side by side: heights and pressure drops against references, solid-fraction maps";
  }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] InputMode inputMode() const override { return InputMode::Gather; }
  void checkParams(const nlohmann::json& resolved, const std::string& pointer,
                   core::json::Diagnostics& diagnostics) const override;
  void checkAgainstUpstream(const nlohmann::json& resolved, const std::string& pointer,
                            const std::vector<UpstreamPlan>& upstream,
                            core::json::Diagnostics& diagnostics) const override;
  void run(StageContext& ctx) const override;

 private:
  params::ParamSchema schema_;
};

}  // namespace grainbridge::workflows::stages
