#pragma once
// `report`: gathers every instance of its upstream stages into one HTML page with a CSV table
// and SVG plots (workflows/report/HtmlReport). Comparison reports of KTGF against tabulated
// closures build on it.
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class ReportStage final : public StageType {
 public:
  ReportStage();
  [[nodiscard]] std::string name() const override { return "report"; }
  // 2: findings first, compact per-stage tables, stage CSVs, plots through report/Plot (issue 16)
  // 3: a findings figure marked wide takes the page's full width (issue 62)
  [[nodiscard]] int implVersion() const override { return 3; }
  [[nodiscard]] std::string summary() const override {
    return "HTML + CSV + SVG report over every instance of the upstream stages";
  }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] InputMode inputMode() const override { return InputMode::Gather; }
  void run(StageContext& ctx) const override;

 private:
  params::ParamSchema schema_;
};

}  // namespace grainbridge::workflows::stages
