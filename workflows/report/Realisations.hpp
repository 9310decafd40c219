#pragma once
// Statistics over realisations (issue 55). A fluidized bed is chaotic: a run is one realisation
// (one seed of its initial perturbation), and two settings are told apart only against the
// spread over several. Runs of one stage whose sweep points agree on every parameter but the
// realisation one form an arm; per arm, an output's mean over its runs, their sample standard
// deviation and the standard error of the mean; between two arms that differ in one parameter,
// the difference of their means with its standard error. Realisations are independent runs, so
// their values are independent samples: no block averaging here (each run's own time average
// and its error are the run's, report/BedRun).
#include <cmath>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "workflows/report/SweepLabel.hpp"

namespace grainbridge::workflows::report {

struct Arm {
  std::string label;                      // its runs' label without the realisation: "bed (rotation_model true)"
  std::string stage;                      // one stage's runs only: two stages are two settings
  nlohmann::json written;                 // the sweep point its runs share, the realisation parameter left out
  std::vector<std::size_t> runs;          // its runs (indices into the grouped list), by realisation value
  std::vector<std::string> realisations;  // their realisation values as written; empty for a run not swept over it
};

// The runs grouped into arms, in label order (then stage). A run not swept over `realisation`
// is an arm of one.
[[nodiscard]] std::vector<Arm> groupArms(const std::vector<SweptRun>& runs, const std::string& realisation);

struct RealisationStatistics {
  std::size_t n = 0;
  double mean = NAN;
  double sd = NAN;  // the sample standard deviation (n - 1 in the denominator); NaN for n < 2
  double se = NAN;  // the standard error of the mean, sd / sqrt(n); NaN for n < 2
};

// Over the realisations' values of one output; mean, sd and se all NaN when a value is not
// finite (a run that did not record the output: the arm has no mean of it).
[[nodiscard]] RealisationStatistics overRealisations(const std::vector<double>& values);

struct MeanDifference {
  double value = NAN;  // to.mean - from.mean
  double se = NAN;     // sqrt(se_from^2 + se_to^2): the arms' runs are independent
  // How many standard errors the difference is (infinite or NaN when se is 0 or NaN).
  [[nodiscard]] double standardErrors() const { return value / se; }
};
[[nodiscard]] MeanDifference meanDifference(const RealisationStatistics& from, const RealisationStatistics& to);

// Two arms of one stage, each of at least two realisations, whose sweep points name the same
// parameters and differ in the value of exactly one: a contrast of that parameter, the other
// settings held.
struct ArmContrast {
  std::size_t from = 0, to = 0;  // indices into the arms, from before to in their order
  std::string parameter;         // as the sweep names it ("rotation_model")
};
[[nodiscard]] std::vector<ArmContrast> armContrasts(const std::vector<Arm>& arms);

}  // namespace grainbridge::workflows::report
