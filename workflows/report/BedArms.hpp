#pragma once
// A comparison of bed runs over realisations (the bed_compare stage, issue 55): each arm's mean
// particle height and, in binary beds, segregation percentage (the runs' time averages) as mean,
// standard deviation and standard error over its realisations (report/Realisations), written as
// arms.csv for programs and as the findings' sentences, which lead with what the study needs: the
// difference between two arms that differ in one setting, in standard errors.
#include <map>
#include <string>
#include <vector>

#include "workflows/report/BedRun.hpp"
#include "workflows/report/Realisations.hpp"

namespace grainbridge::workflows::report {

// The runs' summary values taken over realisations (BedRun::meanHeight and the value of
// segregation_percentage), in arms.csv's order.
inline const std::vector<std::string> kRealisedOutputs = {"mean_height", "segregation_percentage"};

struct BedArm {
  Arm arm;
  std::map<std::string, RealisationStatistics> outputs;  // by kRealisedOutputs entry
};

// The statistics of each arm over its runs (`arms` grouped from `runs`, in the same order).
[[nodiscard]] std::vector<BedArm> bedArms(const std::vector<BedRun>& runs, const std::vector<Arm>& arms);

// arms.csv: arm,realisations,realisation_values,<output>_mean,<output>_sd,<output>_se,...: a row
// per arm, its realisation values as written joined by ';', full precision, an empty field where
// the arm has one run (sd, se) or did not record the output.
[[nodiscard]] std::string armsCsv(const std::vector<BedArm>& arms);

// The findings' sentences: per arm of at least two realisations, its outputs' means with their
// standard errors, "bed (rotation_model true): s_p 66.1 ± 1.2 %, mean height 0.1024 ± 0.0003 m
// (mean and standard error over 3 realisations: seed 1, 2, 3)"; then per contrast
// (report/armContrasts) the difference of the means, its standard error and how many standard
// errors it is. "" when no arm has two realisations. `realisation` names the values ("seed").
[[nodiscard]] std::string armsHeadline(const std::vector<BedArm>& arms, const std::string& realisation);

}  // namespace grainbridge::workflows::report
