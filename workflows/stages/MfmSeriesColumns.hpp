#pragma once
// The columns of an `mfm` stage's series.csv, sampled at every output interval: the pressure drop
// between each pair of taps, the Eq. 5.22 mean particle height and the volume of each solids
// phase, the solver's last time step, and each phase's mass account (held, in, out). Samples inside the averaging window are kept for the
// summary's block averages, and the frames of the window for the time-averaged fields.
#include <map>
#include <string>
#include <vector>

#include "core/averaging/FieldTimeAverage.hpp"
#include "engines/mfm/MfmEngine.hpp"
#include "workflows/driver/SeriesColumns.hpp"
#include "workflows/stages/MfmSetup.hpp"

namespace grainbridge::workflows::stages {

// The boundary mass account's columns (engines/fluid/BoundaryFlow): per phase, the gas first,
// `mass_<phase>` held [kg], `mass_in_<phase>` and `mass_out_<phase>` crossed since the start
// [kg], then `mass_out_<phase>_<outlet>` for each pressure outlet. `outletSides` has one entry per
// boundary patch: the side's name ("x_high") for an outlet, "" otherwise. An outlet is named by
// its side, or "<side>_<patch index>" where two outlets share a side.
[[nodiscard]] std::vector<std::string> outletLabels(const std::vector<std::string>& outletSides);
[[nodiscard]] std::vector<std::string> massAccountColumns(const std::vector<std::string>& phases,
                                                          const std::vector<std::string>& outletSides);

class MfmSeriesColumns final : public driver::SeriesColumns {
 public:
  // `stage` names the log lines: ten times over the run, the solver's state (the residual history).
  MfmSeriesColumns(const mfm::MfmEngine& engine, const MfmSetup& setup, std::string stage);
  [[nodiscard]] std::vector<std::string> names() const override { return names_; }
  void sample(driver::SeriesRow& row) override;

  // The samples of each column taken at or after the window's start, in time order.
  [[nodiscard]] const std::map<std::string, std::vector<double>>& windowSamples() const { return window_; }
  // The times of those samples.
  [[nodiscard]] const std::vector<double>& windowTimes() const { return windowTimes_; }
  [[nodiscard]] const core::averaging::FieldTimeAverage& fieldAverage() const { return fields_; }

 private:
  const mfm::MfmEngine& engine_;
  const MfmSetup& setup_;
  std::vector<std::string> names_;
  std::vector<std::size_t> outlets_;  // the patches that are pressure outlets
  std::string stage_;
  long lastSteps_ = 0, lastIterations_ = 0, lastRetries_ = 0;
  double nextLog_ = 0.0;
  std::map<std::string, std::vector<double>> window_;
  std::vector<double> windowTimes_;
  core::averaging::FieldTimeAverage fields_;
};

}  // namespace grainbridge::workflows::stages
