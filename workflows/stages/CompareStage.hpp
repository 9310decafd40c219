#pragma once
// `compare`: DEM-extracted closures beside kinetic theory at the same state. Gathers extract
// instances; for each closure point it evaluates every kinetic-theory model of
// engines/closures (lun1984 first: the model the reference's Chapter 5 ran) and writes the
// relative deviations as CSV and SVG plots (gnuplot) with an HTML page.
//
// Under simple shear the comparison is in shear units, as kinetic theory predicts it: steady
// shear balances shear work and collisional dissipation, mu(T) gammadot^2 = J(T); with
// mu = mu1 sqrt(T) and J = J1 T^(3/2) (both models, no gas) that gives T = (mu1/J1)
// gammadot^2, and p*, tau*, T* follow at that temperature. Without shear (a cooling gas, a
// fluidized cell) the theta-scaled forms p/(rho theta) and J d/(rho theta^(3/2)) are compared
// at the measured temperature.
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class CompareStage final : public StageType {
 public:
  CompareStage();
  [[nodiscard]] std::string name() const override { return "compare"; }
  // 2: comparison.csv without the extract key column
  // 3: figures through report/Plot (literal text, units, legend below, PNG copies), findings
  // 4: lun1984_mfix (MFiX's 1.2 x shear viscosity) among the models DEM is compared with
  // 5: figures as wide as their title and legend need (report/Plot)
  // 6: mu(I) and phi(I) figures with their fits beside kinetic theory's steady shear
  // 7: each DEM series' table drawn as a band of ± one standard error (issue 31)
  // 8: ordered boxes drawn apart and left out of bands and fits; the power-law fits beside Jop's
  //    and the line, each with its chi2/dof (issue 61)
  [[nodiscard]] int implVersion() const override { return 8; }
  // The headline and its table are the findings; the report's row shows how many points.
  [[nodiscard]] std::vector<ResultColumn> keyResults() const override { return {{"points", "–"}}; }
  [[nodiscard]] std::string summary() const override {
    return "DEM closures against kinetic theory (lun1984, syamlal_algebraic): CSV, plots and an HTML page";
  }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] InputMode inputMode() const override { return InputMode::Gather; }
  // Every upstream must record closure points (extract's plannedOutput says so).
  void checkAgainstUpstream(const nlohmann::json& resolved, const std::string& pointer,
                            const std::vector<UpstreamPlan>& upstream,
                            core::json::Diagnostics& diagnostics) const override;
  void run(StageContext& ctx) const override;

 private:
  params::ParamSchema schema_;
};

}  // namespace grainbridge::workflows::stages
