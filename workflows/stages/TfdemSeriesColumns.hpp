#pragma once
// The columns of a `tfdem` stage's series.csv, sampled at every output interval: the gas pressure
// drop between each pair of taps, the particles' mean height (arithmetic, along gravity), their
// contacts, bulk coordination number and multi-contact ratio (Figs. 7.5, 7.11), and the outer
// iterations of the last gas step. Samples inside the averaging window are kept for the summary.
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

  // The samples of each column taken in the window [average_from, average_to], in time order.
  [[nodiscard]] const std::map<std::string, std::vector<double>>& windowSamples() const { return window_; }

 private:
  tfdem::TfdemEngine& engine_;
  const TfdemStageSetup& setup_;
  std::vector<std::string> names_;
  std::map<std::string, std::vector<double>> window_;
};

}  // namespace grainbridge::workflows::stages
