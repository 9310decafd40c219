#pragma once
// The columns of a `tfdem` stage's series.csv, sampled at every output interval: the gas pressure
// drop between each pair of taps, the particles' mean height (arithmetic, along gravity) and Eq.
// 5.22's of the particles' deposited fraction (what a multi-fluid run reports), their contacts,
// bulk coordination number and multi-contact ratio (Figs. 7.5, 7.11), and the outer iterations of
// the last gas step. The stage averages the window from series.csv (a resumed run's too).
#include <map>
#include <string>
#include <vector>

#include "engines/tfdem/TfdemEngine.hpp"
#include "workflows/driver/SeriesColumns.hpp"
#include "workflows/stages/TfdemSetup.hpp"

namespace grainbridge::workflows::stages {

class TfdemSeriesColumns final : public driver::SeriesColumns {
 public:
  TfdemSeriesColumns(tfdem::TfdemEngine& engine, const TfdemStageSetup& setup);
  [[nodiscard]] std::vector<std::string> names() const override { return names_; }
  void sample(driver::SeriesRow& row) override;

 private:
  tfdem::TfdemEngine& engine_;
  const TfdemStageSetup& setup_;
  std::vector<std::string> names_;
};

}  // namespace grainbridge::workflows::stages
