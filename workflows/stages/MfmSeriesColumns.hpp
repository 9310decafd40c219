#pragma once
// The columns of an `mfm` stage's series.csv, sampled at every output interval: the pressure drop
// between each pair of taps, the Eq. 5.22 mean particle height and the volume of each solids
// phase, and the solver's last time step. Samples inside the averaging window are kept for the
// summary's block averages, and the frames of the window for the time-averaged fields.
#include <map>
#include <string>
#include <vector>

#include "core/averaging/FieldTimeAverage.hpp"
#include "engines/mfm/MfmEngine.hpp"
#include "workflows/driver/SeriesColumns.hpp"
#include "workflows/stages/MfmSetup.hpp"

namespace grainbridge::workflows::stages {

class MfmSeriesColumns final : public driver::SeriesColumns {
 public:
  // `stage` names the log lines: ten times over the run, the solver's state (the residual history).
  MfmSeriesColumns(const mfm::MfmEngine& engine, const MfmSetup& setup, std::string stage);
  [[nodiscard]] std::vector<std::string> names() const override { return names_; }
  void sample(driver::SeriesRow& row) override;

  // The samples of each column taken at or after the window's start, in time order.
  [[nodiscard]] const std::map<std::string, std::vector<double>>& windowSamples() const { return window_; }
  [[nodiscard]] const core::averaging::FieldTimeAverage& fieldAverage() const { return fields_; }

 private:
  const mfm::MfmEngine& engine_;
  const MfmSetup& setup_;
  std::vector<std::string> names_;
  std::string stage_;
  long lastSteps_ = 0, lastIterations_ = 0, lastRetries_ = 0;
  double nextLog_ = 0.0;
  std::map<std::string, std::vector<double>> window_;
  core::averaging::FieldTimeAverage fields_;
};

}  // namespace grainbridge::workflows::stages
